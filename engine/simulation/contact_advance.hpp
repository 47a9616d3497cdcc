// The static solver's contact step bound advanced along the step (issue 39, paper mode's creep).
// contactStepBound (contact.hpp) takes a vertex's whole motion against a triangle as closing on
// it, so a flap's tip sliding over the layer under it at a steady gap (vertex6_s2 folded flat:
// 2 um of closing along a step of 9 mm) has its step cut to gap / motion, about 0.5%, every
// iteration. Here each vertex-triangle pair that bound would cut is advanced along the step by
// conservative advancement: the gap changes at most by that motion per unit of the share, so from
// a share where it is g the share may grow by (g - g0 / 10) / motion, and the bound is taken again
// from there (up to 2000 rounds a pair) until the whole step, or until an advance falls under 0.1%
// of the share reached (the gap closing on a tenth of its start).
//
// Edge pairs (ContactOptions::edgePairs) are advanced alike on
// the segments' distance (the largest relative motion of an end of one against an end of the
// other bounds its change): the edges of flat-folded layers slide over each other as the tips do.
//
// Inputs: the model (paper mode's contact), the positions and the step (one vector per vertex).
// Output: a share (0..1] of the step, never below contactStepBound's, along which no pair's gap
// falls below a tenth of its start (pairs already inside the thickness not counted). Limits:
// costs up to 2000 distances for each pair the one-shot bound cuts; a slide whose one-shot share
// 0.9 gap / motion is under 1e-3 stops near a thousand times it, not at 1; with edge pairs off
// it cannot keep edges from passing through edges. Defined in contact.cpp beside
// contactStepBound, whose pair search it shares. Used by the static solver only with edge pairs
// on, after kAdvanceAfterCuts (20) one-shot cuts in a row (static_solver.cpp; contact19 and
// contact20 in docs/performance.md).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

namespace curvefold {

struct BarHingeModel;

double advancedContactStepBound(const BarHingeModel& model,
                                const std::vector<glm::dvec3>& positions,
                                const std::vector<glm::dvec3>& step);

}  // namespace curvefold
