// A steep cup's floor closed from a cone start (issue 38, 2): the band of the placed cone that
// reaches past the cup's floor turned inward, toward the axis, by a ring of folds through the
// heel, its flaps stacked a small gap apart.
//
// Why a band and a ring: a cone fitted to a cup's wall ends open at the floor, so the floor's
// centre stays as far from the sheet as the hole's radius (docs/performance.md, issue 38, cup23);
// the cone placed across the profile (placed_start.hpp: its line spans the profile's extreme
// projections) reaches past the floor's height, narrower than the heel, and that end is the band. A
// fold along a circle keeps a tube's radius (profile_folds.hpp), so no single reflection lays the
// tube's paper across the floor; a ring of n planes, plane k through the chord of the heel's circle
// at cos(pi / n) of its radius r, tilted by `tilt` from the radial direction toward the floor (45
// degrees turns an upright wall level), folds the band past the floor inward. Each flap is the band
// reflected: a piece of a cylinder of the wall's radius lying across the axis, its middle line
// level just inside the floor and reaching about d inward for a band d long, its sides rising past
// the floor by up to d (a tube reflected is a tube), so the floor's centre comes to about max(d, r
// cos(pi / n) - d) of the sheet, not to zero. Flaps of one ring overlap near the axis (the band
// holds more paper than the floor's circle); plane k lies `gap` k nearer the rim than plane 0, so
// the flaps lie in layers, not in one plane (in one plane they would cross or touch: reflections
// make exact layers). Every ring is made on the sheet, refused where it passes the sheet through
// itself, and kept only where it brings the sheet nearer by the tube rings' measure
// (ring_folds.hpp), so a cup reached now never gets farther.
//
// Known limits: the placed cone is not continued toward its apex (tried: by half its radius past
// the floor, it made marched_mug_mm's first step find no fold at all, Chamfer 2.28% -> 2.75%);
// one ring; a flap's sides stand past the floor by the band's length (on a
// 40 mm heel: the floor's centre 40 -> 15-17 mm, the sides 11 mm out, against a flat floor's
// bound of 0); the floor is found only where the target's samples facing along its axis (within
// 30 degrees) at the narrow end are many; a rounded heel is treated as the floor's edge at the
// mean height of those samples.
#pragma once

#include <cstddef>
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

// The target's floor across its axis through `point` along `direction` (unit): the end past the
// samples' mean height along `direction` (tried first) or its opposite where the samples facing
// along the axis (within 30 degrees) are at least 4% of all samples; `toward` points past it (the
// way from the wall to the floor), `height` is those samples' mean height along it from `point`.
// None where neither end has one (a vase's open neck, a tube).
struct TargetFloor {
  glm::dvec3 toward{0.0};
  double height = 0.0;
};
std::optional<TargetFloor> targetFloor(const std::vector<SurfaceSample>& samples,
                                       const glm::dvec3& point, const glm::dvec3& direction);

// One floor ring's shape: n planes through the heel's chords (see above).
struct FloorRingShape {
  int order = 4;
  double tilt = 0.0;  // radians from the radial direction toward the floor
  double gap = 0.0;   // between successive planes, along the axis, in metres
  double turn = 0.0;  // of the first plane about the axis
};

// The planes of `shape` about the axis through `point` along `toward` (unit, past the floor),
// through the heel at `height` along it and radius `radius` (the sheet's there).
Ring floorRingOf(const FloorRingShape& shape, const glm::dvec3& point, const glm::dvec3& toward,
                 double height, double radius);

// The floor rings to try on the sheet whose vertices are `positions`, toward a target whose
// floor is `floor` about the axis through `point`: none where the sheet reaches past the floor
// by under a tenth of its radius there. `radius` is set to that radius (the heel's).
std::vector<FloorRingShape> floorRingShapes(const std::vector<glm::dvec3>& positions,
                                            const glm::dvec3& point, const TargetFloor& floor,
                                            double& radius);

// The floor ring (of floorRingShapes, each made on a session of its own from `session`'s folds
// and refused where it passes the sheet through itself, unless the fitter allows that) whose
// sheet scores least by the tube rings' measure (Chamfer + kTubeHausdorffWeight Hausdorff,
// surfaceDistance, 1500 samples a side), when under `current` (that measure of the session's
// sheet); none where the target (the fitter's, whose samples are `targetSamples`, about `axis`)
// has no floor, the sheet reaches too little past it, or the clock cut the scoring.
struct FloorRing {
  Ring ring;
  double measured = 0.0;
};
std::optional<FloorRing> bestFloorRing(const FoldSession& session, const FoldFitter& fitter,
                                       const RevolutionAxis& axis,
                                       const std::vector<SurfaceSample>& targetSamples,
                                       double current, const Deadline& deadline);

// The tube rings' measure of `sheet` against the fitter's target (see above).
double floorMeasure(const Sheet& sheet, const FoldFitter& fitter);

// Each ring made on its own copy of `session` (RingTrials, on all cores) and measured by
// floorMeasure; a ring not made, or one passing the sheet through itself more than it did (unless
// the fitter allows it), scores 1e300. std::nullopt where the deadline passed (the scores are
// partial). One home for the floor ring's and the lip pleats' trials (lip_pleats.hpp).
std::optional<std::vector<double>> floorMeasuresOf(const FoldSession& session,
                                                   const FoldFitter& fitter,
                                                   const std::vector<Ring>& rings,
                                                   const Deadline& deadline);

// The best floor ring as one step of the search (the session unchanged): its `after` the
// search's distance before scaled by the measure's fall, as the tube rings' (ring_folds.hpp).
// With `first` (a suggestion made on this session), the floor ring is made after its folds and
// the step is both: a step's rings and the floor under them are offered together, so a fit
// whose evaluations end after one step keeps both.
std::vector<FoldSuggestion> suggestFloorRing(const FoldSession& session, const FoldFitter& fitter,
                                             const RevolutionAxis& axis,
                                             const std::vector<SurfaceSample>& targetSamples,
                                             const Deadline& deadline,
                                             const FoldSuggestion* first = nullptr);

}  // namespace curvefold
