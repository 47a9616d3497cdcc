// A flare's lip turned out (issue 38, 2: lampshades, bells, trumpets, tulips), as a paper artist
// steps a cone's lip out: pleats across the axis, each a pair of folds whose planes are parallel.
//
// Why pleats: a flaring target's radius is a convex function of height (it grows faster toward
// the lip), so the cone placed through its profile (placed_start.hpp) stands outside it in the
// middle and inside it at both ends, and every ring of folds turns a part toward the axis (a
// ring's envelope is concave: ring_folds.hpp), so the lip stays inside. Two reflections through
// parallel planes compose to a translation along their normal by twice their distance (the
// classical theorem, as for pleat_folds.hpp's rotation): the first plane, across the axis at
// height a, turns the part toward the wide end back over the sheet; the second, at a - w, turns
// it forward again. The wide end then lies 2 w nearer the apex, where the cone of slope s is
// 2 w s wider: a step out by 2 w s at a - w, the flap between the two creases lying between the
// layers (its radius between theirs: nothing crosses). A staircase of such steps, each step
// solved on the radius profile so the shifted cone meets the target's radius halfway to the next
// step, follows the flare; every step shortens the sheet by 2 w along the axis (its wide end
// retreats), so each staircase is also made at 0.6 of its shifts.
//
// Inputs: a session whose sheet is a bare cone about the target's axis (tubeAbout, any taper from
// 0.05 to kLipSteepestTaper: a cylinder has no step to give), the target's area-uniform samples
// about `axis`. Each staircase (1 to 6 steps, from three heights where the target first stands
// out of the cone toward its wide end, at two scales) is made on its own copy of the session,
// refused where it passes the sheet through itself (unless the fitter allows it), and measured as
// the tube rings are (Chamfer + kTubeHausdorffWeight Hausdorff, floorMeasure); the nearest is
// offered as one step when it is nearer than the bare cone. Known limits: the cone's narrow end
// keeps its gap (a pleat shifts the part beyond it toward the apex, narrower, never wider); the
// steps are level (a circle's crease on the cone), so the envelope is a staircase, not a curve,
// with each flap's edge standing out at its step; the wide end retreats by the pleats' widths.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/sheet.hpp"

namespace curvefold {

// The steepest cone stepped out (its radius changes by this much per length along its axis).
inline constexpr double kLipSteepestTaper = 3.0;

// A bare cone about an axis: `axis.direction` points toward its wide end, heights from
// `axis.point` along it; radius(t) = radius + slope t over [lowest, highest].
struct ConeProfile {
  RevolutionAxis axis;
  double radius = 0.0, slope = 0.0, lowest = 0.0, highest = 0.0;
};
std::optional<ConeProfile> coneProfile(const Sheet& sheet, const glm::dvec3& direction);

// One step: the creases across the axis at heights `crease` and `crease - width` (width > 0).
struct LipStep {
  double crease = 0.0, width = 0.0;
};

// The staircases to try on `cone` toward the target whose samples are `targetSamples`.
std::vector<std::vector<LipStep>> lipStaircases(const ConeProfile& cone,
                                                const std::vector<SurfaceSample>& targetSamples);

// The two folds of each step, in order (each step's heights as the steps before it left the
// sheet: they lie past the steps before).
Ring lipPleatRing(const ConeProfile& cone, const std::vector<LipStep>& steps);

// The nearest staircase as one step of the search (the session unchanged), its `after` the
// search's distance before scaled by the measure's fall (as suggestFloorRing); none where the
// sheet is no bare cone about the axis, the target stands out of it nowhere toward its wide end,
// no staircase comes nearer, or the clock cut the scoring.
std::vector<FoldSuggestion> suggestLipPleats(const FoldSession& session, const FoldFitter& fitter,
                                             const RevolutionAxis& axis,
                                             const std::vector<SurfaceSample>& targetSamples,
                                             const Deadline& deadline);

}  // namespace curvefold
