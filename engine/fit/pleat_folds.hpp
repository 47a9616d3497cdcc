// Pleats toward a doubly curved target (issue 38, 2): a pair of reflection folds that turns the
// end of the sheet beyond a line by a small angle about that line, keeping the end's own shape.
//
// Method: two reflections compose to a rotation about the line where their planes meet, by twice
// the angle between them (the classical theorem of plane reflections, as in any text on
// isometries; see Demaine & O'Rourke, "Geometric Folding Algorithms", 2007, on folding, and
// on the pleated hypar Demaine, Demaine, Hart, Price & Tachi, "(Non)existence of Pleated Folds",
// Graphs and Combinatorics 2011). A
// paper artist bends a cylinder's ends down this way to approximate a saddle: the sheet's own
// curvature (a swept parabola's) stays, and pleats across the other direction add the other,
// opposite curvature that no developable sheet has. Here the first fold turns the end back over
// the sheet (a flap rising at a small angle, 2 eps, from a plane through the hinge point tilted
// by eps), the second turns the flap's far part forward again (a plane through the flap at the
// pleat's width, the bisector of the flap's direction and the wanted one): the end leaves the
// pleat turned by theta (< 2 eps, so it passes over the first crease) toward the target. The
// first fold alone takes the sheet far from the target: a search of single folds, each of which
// must bring the sheet closer, never finds it (fold_fit.hpp's known limit).
//
// Where (solved, as a corrugation is laid out): the target's height over the sheet, along the
// sheet's normal, at a spread of its vertices; for each direction in the sheet's plane (8 over a
// half turn, both ways) and each hinge across it, the turn of the end beyond the hinge that best
// fits that height in least squares (a rigid turn adds height in proportion to the distance from
// the hinge, so the fit is linear); the hinges that remove the most squared height made, then the
// best nudged (hinge and turn) a few times, since the model leaves out the width a pleat folds
// away. On a curved sheet (not a flat one) both ends of a line through it (a direction and its
// opposite) are also pleated as one step of four folds, each end's hinge and turn solved as above
// (their ends do not overlap, so the gains add): a saddle falls (or rises) on both sides of its
// middle, and one end's pleat alone leaves the other as far, costing the search a step and the
// clock its time. Before them, from a curved sheet toward a target with no axis (a saddle), a
// family: several hinges evenly spaced along one line through the sheet, the piece between two
// of them kept in place and each hinge turning all of the sheet beyond it, the turns solved
// together in least squares from the target's height straight over the sheet (along its mean
// normal, stepped to the target's tangent plane: the closest point's height alone says too little
// where a saddle's ends fall steeply) as a paper artist lays parallel pleats; each pleat's planes,
// solved on the sheet as it was, moved with its end by the pleats made before it there; the best
// family of each count (3 to 8 hinges) made at 0.9 and 0.65 of its turns (each pleat folds away
// paper the model leaves out), kept only where the sheet's exact farthest point does not move away
// (that paper can leave an end short of the target's). Repeated step by step, the pleats
// approximate the target's second curvature piecewise. From a flat sheet (a square) toward a
// target with no axis, first a cross as one step: both ends of a line through the sheet bent (one
// fold each: on a flat sheet a reflection through a plane at half the turn about the hinge turns
// the end), then both ends of the line across it pleated on the sheet the bends left (its ends
// keep their bend, which one reflection would flip; pleats on both lines crossed each other's
// layers, the paper passing through itself), the four turns solved together from the target's
// heights (ramps beyond each hinge, as a family's), for 8 directions over a half turn from the
// heights' most curved direction (a quadric's; not the sheet's own axes, which a square or a
// disk gives turned anyhow; either line bent first) and 4 x 4 hinge places, the best 4 made at
// their turns and at 0.7 of them: a saddle rises at two opposite ends and falls at the other two,
// and a pleat per step leaves three ends as far (the farthest point unchanged). Only where no
// solved pleat helps, the blind way of before: hinges on the way from the sheet's centre toward its
// vertices farthest from the target, bends on a grid. Each pleat is made on the real sheet
// (FoldSession: a sliver is refused as a designer's drag is), scored with
// FoldFitter::approximateDistance, checked for self-intersection, and taken back.
//
// Inputs: a session holding a design without symmetry (a symmetric one gets none: its images
// would need a pleat group of their own); the fitter's target. Output: up to `count` pleats, each
// a FoldSuggestion of two folds (four for both ends' pair, more for a family, one group), best
// first, each bringing the sheet closer. Known limits: the hinge is straight only where the sheet
// is ruled across it (a swept sheet across its rulings, a flat one); each pleat shortens the sheet
// by twice its width (0.3% of the target's diagonal, more where the sheet rises across the hinge: a
// family of n pleats shortens it n times that, which its model does not see), and turning a curved
// end about a straight hinge shears it (its high points move in, its low ones out), which costs
// Hausdorff distance at the ends; parallel pleats give one direction's curvature, not a twist (a
// hypar z = xy is fitted along its principal directions, not its rulings).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/geometry/fold_session.hpp"

namespace curvefold {

// The two planes of a pleat at `hinge` (a point of the sheet), turning the part beyond it along
// the unit tangent `along` by `theta` radians toward `bendToward` (a unit vector across the
// sheet, perpendicular to `along`), with the flap at 2 * `flapTilt` (> theta) and `width` wide.
// Reflecting a point beyond the hinge in `first`, then in `second`, turns it about a line along the
// hinge.
struct PleatPlanes {
  ReflectionPlane first, second;
};
PleatPlanes pleatPlanes(const glm::dvec3& hinge, const glm::dvec3& along,
                        const glm::dvec3& bendToward, double theta, double flapTilt, double width);

// Up to `count` pleats for the design `session` holds, best first (see above). The session is
// left as it was. `step` varies which far points are tried.
std::vector<FoldSuggestion> suggestPleats(FoldSession& session, const FoldFitter& fitter,
                                          std::size_t count, const Deadline& deadline,
                                          std::uint64_t step = 0);

}  // namespace curvefold
