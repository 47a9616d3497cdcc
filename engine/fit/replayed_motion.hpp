// What is left to move after the folds read are replayed (issue 38, 1). A target made by folds
// and then moved whole unfolds (target_unfolding.hpp) to a copy of the sheet moved by a rigid
// motion T (whole_sheet_folds.hpp). Where the design is symmetric, a fold's image may itself have
// moved the whole sheet (its plane missed it), and the fold read, replayed, brings that image
// again: the sheet the replay folds is then not where T assumes, and what is left to move is not
// T. So it is measured: each target vertex names, through where its unfolding lies on the sheet,
// a point of the development, which names a point of the replayed sheet; the rigid motion taking
// those points onto the target vertices is Umeyama's closed form [Umeyama 1991].
//
// A symmetric sheet lies on the unfolded copy several ways (T times any symmetry s of the sheet,
// a continuous family for a cylinder or a disk), and the motion left is then W s, W the designer's
// own. Where W was one fold (a mirror), it is found in closed form: every symmetry fixes the
// sheet's centre c, so W takes c where W s does, and the mirror is the plane bisecting c and its
// image (fewerPlaneRests). The caller replays the folds read moved by the symmetry that makes it.
//
// Known limits: a rest made by two or more whole-sheet folds is not reduced past the design's own
// symmetry's images; the motion is refused (nothing) unless every pair lies within `tolerance`.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/fit/whole_sheet_folds.hpp"
#include "engine/geometry/sheet.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

// The rigid motion taking `folded` (`initial` folded by any folds) onto `target`, where target
// vertex v lies at `onSheet[v]` on `initial` (its unfolding, moved onto the sheet). Up to a few
// hundred vertices spread over the target, off its boundary (a slit's two sides lie at one place).
// Where the pairs do not all move rigidly within `tolerance` (metres), the largest group of them on
// one side of each of `planes` (the folds read, on the sheet) that does (a fold made from a seed
// across its plane moves the other part: the same form, each part's pairs moved apart); nothing
// when none does.
std::optional<RigidMotion> restOntoTarget(const Sheet& initial, const Sheet& folded,
                                          const std::vector<glm::dvec3>& onSheet,
                                          const TriangleMesh& target,
                                          const std::vector<ReflectionPlane>& planes,
                                          double tolerance);

// Motions `rest` may be written as, `rest` times a symmetry of the sheet (about `centre`), that
// take fewer whole-sheet folds: the mirror through the plane bisecting `centre` and rest(centre),
// and rest times each of `images` (the design's symmetry). Each with the symmetry s (rest = W s):
// the folds read moved by s make the sheet that W moves onto the target.
struct FewerPlaneRest {
  RigidMotion rest;      // W
  RigidMotion symmetry;  // s, x -> s x about the world origin
};
std::vector<FewerPlaneRest> fewerPlaneRests(const RigidMotion& rest, const glm::dvec3& centre,
                                            const std::vector<Isometry>& images);

// `motion` made exactly what one plane (a mirror) or two (a turn about a line with no shift along
// it, or a shift) make, where it lies within `angle` (radians) and `shift` (metres) of one; else
// `motion`. A motion measured on a replay is about 1e-6 off, and two planes make only a turn with
// no shift along its axis at all (whole_sheet_folds.hpp).
RigidMotion snappedToFewPlanes(const RigidMotion& motion, double angle, double shift);

// Whether `motion` maps `initial` onto itself: each of up to a few hundred of its vertices within
// `tolerance` (metres) of the sheet after it.
bool isSymmetryOf(const RigidMotion& motion, const Sheet& initial, double tolerance);

}  // namespace curvefold
