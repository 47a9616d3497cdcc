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
// sheetSymmetries: the sheet's own discrete symmetries (a disk's n-gon's n turns and n flips, each
// also through the flat sheet's plane), found from its boundary: each turn or flip about a
// principal axis of the boundary (through its centroid) that takes one boundary vertex onto
// another, kept where every boundary vertex lands on the boundary and the sheet on itself. A
// registered way times each is a way too (registerSheetOntoAll's starts, every 15 degrees, reach
// only some of an n-gon's), and the fit takes those needing the fewest whole-sheet folds
// (fewestReflections): the design's own way among them.
//
// Known limits: a sheet's continuous symmetry (a slit cylinder's turn, when no slit is read) is
// handled by registration's boundary turn, not here: only turns that take a boundary vertex onto
// another are tried. A copy that is not rigid (creases left) is refused.
#pragma once

#include <optional>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "engine/fit/deadline.hpp"
#include "engine/fit/rigid_motion.hpp"
#include "engine/geometry/reflection.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

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

// A whole-sheet fold placed among the folds read: made after `after` of them (0: before the
// first), through `plane` as the sheet lies then (moved by the whole-sheet folds before it).
struct PlacedPlane {
  ReflectionPlane plane;
  std::size_t after = 0;
};

// Planes, in folding order, whose reflections make `motion`, each placed among the folds read
// where it misses the sheet: `stages[k]` is the sheet after the first k folds read as they lie
// with every whole-sheet fold last (stages[0] the sheet itself), so the motion is what is left
// to move the last stage onto the target. A plane made after k folds acts on the stage k moved
// by the planes before it, and every later fold read is then made moved by it too (its plane
// reflected through it, its seed in the development as before), so the form ends moved by
// `motion` whatever the places. A design whose whole-sheet folds came between creasing ones
// (C C W C C W C C) may take no planes that miss the first or the last stage (a turn about a
// line through both) and yet the planes it was made with, placed where it made them.
// One plane (a mirror) and two (a turn about a line, tried every half degree about it, or a
// shift) are placed one by one, each at the earliest stage it misses; three or more all at one
// stage (wholeSheetReflections on it). Empty where no placement is found.
std::vector<PlacedPlane> placedWholeSheetReflections(
    const RigidMotion& motion, const std::vector<std::vector<glm::dvec3>>& stages,
    std::size_t count);

// The sheet's discrete symmetries other than the identity (see above): motions taking every
// boundary vertex within `tolerance` (metres) of the boundary and every so many vertices within it
// of the sheet. Empty for a sheet with none (or no boundary).
std::vector<RigidMotion> sheetSymmetries(const TriangleMesh& sheet, double tolerance);

// The fewest reflections that make `motion` by its kind [Cartan-Dieudonne]: 0 the identity, 1 a
// mirror, 2 a turn about a line or a shift, 3 an improper motion that is no mirror, 4 a screw;
// `angle` (radians) and `shift` (metres) how far from the fewer kind still counts as it (a
// measured motion is a little off). Whether planes that many miss the sheet is not asked
// (wholeSheetReflections is).
std::size_t fewestReflections(const RigidMotion& motion, double angle, double shift);

}  // namespace curvefold
