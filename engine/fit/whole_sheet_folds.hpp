// Folds that move the whole sheet (issue 38, 1). A fold whose plane misses the sheet reflects all
// of it and leaves no crease (a drag away from the sheet's edge does this often), so a target
// made with such folds unfolds (target_unfolding.hpp) to a smooth copy of the sheet moved by a
// rigid motion: the product of those folds, proper or improper. Its creases are read all the
// same; what is missing is the motion, found here and written back as folds.
//
// registerSheetOnto: the rigid motion that lays the sheet on a moved copy of itself. Started from
// the principal axes of area-uniform samples (every sign, and turns about each axis, since a
// square's or a disk's axes are not unique), the best starts refined by ICP against exact
// closest points, each step point-to-plane [Chen & Medioni 1992] Gauss-Newton damped as
// Levenberg-Marquardt, with a second row along the surface for a point past the copy's boundary
// (an improper motion as a proper one after a fixed mirror). Refined on every boundary vertex:
// on a sheet with a near-continuous symmetry (a disk, a 96-gon, turned about its normal; a slit
// cylinder about its axis) only the corners or the slit hold the turn, and point-to-point steps
// [Besl & McKay 1992], which the interior pins where it is, slid there for hundreds of steps.
// A way counts only where the boundaries lie on each other too (every boundary vertex of each
// within the tolerance of the other's boundary): a slit cone or cylinder is whole in space and
// lies on its copy turned any way about its axis, and only the slit says which turn the
// development's folds were made on. A way that lays the surface but not the boundary is turned
// about each of the sheet's principal axes (every degree) to where the boundaries meet, then
// refined holding each boundary vertex to the copy's boundary (point to point); kept as it was
// where no turn lays them (a copy whose boundary differs: a slit welded shut).
//
// wholeSheetReflections: reflections whose product is the motion, each plane missing the sheet as
// it lies then, so each is a fold of the whole sheet: one plane (a mirror), two (a turn about a
// line off the sheet, or a shift), else the motion's linear part as Householder reflections
// [Cartan-Dieudonne] through planes pushed off the sheet and a shift by two parallel planes (at
// most five).
//
// registerSheetOntoAll: every way the sheet lies on the copy (a symmetric sheet, a square, a disk
// or a star, lies on it several ways, one its symmetry times another), as the starts above find
// them: each needs its own number of whole-sheet folds, and the fit takes the fewest (a fold
// that mirrors a star whole is one plane; the star's symmetry times it may take five).
//
// Known limits: a disk (a 96-gon) lies on its copy in 192 ways, each turn of its corners; those
// found are the ones the starts (every 15 degrees) lead to. A copy that is not rigid
// (creases left) is refused.
#pragma once

#include <optional>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "engine/fit/deadline.hpp"
#include "engine/geometry/reflection.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

// x -> linear x + offset, linear orthogonal.
struct RigidMotion {
  glm::dmat3 linear{1.0};
  glm::dvec3 offset{0.0};
  glm::dvec3 operator()(const glm::dvec3& x) const { return linear * x + offset; }
};

// The motion taking `sheet` onto `moved`, when every vertex of each lies within `tolerance`
// (metres) of the other after it; nothing otherwise.
std::optional<RigidMotion> registerSheetOnto(const TriangleMesh& sheet, const TriangleMesh& moved,
                                             double tolerance);

// Every distinct motion taking `sheet` onto `moved` within `tolerance` as above, at most `most`,
// the best start's first.
// Stops at `deadline` with the ways found by then: checked at every step of each refinement (a
// refinement on every vertex of a large sheet takes seconds), so it returns within about one
// step (one closest-point pass) of the deadline; a refinement cut short counts no way.
// `steps`, when given, counts the refinement steps taken (each one closest-point pass over the
// points refined): a measure of the work that does not depend on the clock.
std::vector<RigidMotion> registerSheetOntoAll(const TriangleMesh& sheet, const TriangleMesh& moved,
                                              double tolerance, std::size_t most,
                                              const Deadline& deadline = {}, int* steps = nullptr);

// Planes, in folding order, whose reflections make `motion` and each miss the sheet (`points`:
// its vertices) where the earlier ones left it. Empty for the identity.
std::vector<ReflectionPlane> wholeSheetReflections(const RigidMotion& motion,
                                                   const std::vector<glm::dvec3>& points);
// The same, only `count` planes (1 to 5): empty where this finds no way with that many. Cheap for
// 1 and 2; 3 searches (the fit asks for fewer first, over every way the sheet lies on its copy).
std::vector<ReflectionPlane> wholeSheetReflections(const RigidMotion& motion,
                                                   const std::vector<glm::dvec3>& points,
                                                   std::size_t count);

}  // namespace curvefold
