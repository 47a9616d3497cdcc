// What a simulated state is reported with: each edge's strain and each crease's angle error,
// their largest (and the creases' mean), the creases folded to the wrong side of flat or past
// flat-folded, and the triangle pairs that cross. `curvefold simulate` prints it for every state
// and Python's simulate returns it, from this one function, so the two report the same numbers.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/static_solver.hpp"

namespace curvefold {

struct StateReport {
  std::vector<double> strain;      // per pattern edge (edgeStrain)
  std::vector<double> angleError;  // per pattern edge, degrees (creaseAngleError)
  double largestStrain = 0.0;      // largest |strain|
  double largestAngleError = 0.0;  // largest |angle error|, degrees
  double meanAngleError = 0.0;     // mean |angle error| over crease hinges (0 without one)
  // Creases with a target folded to the other side of flat than it by more than half a degree (a
  // mountain folded as a valley, which paper folding the printed pattern would not do), and those
  // past flat-folded (through the paper), by the unwrapped angle.
  std::size_t wrongSideCreases = 0;
  std::size_t pastFlatCreases = 0;
  std::size_t crossingPairs = 0;  // triangle pairs crossing (crossingTrianglePairs, as `check`)
};

// Inputs: the model, a state of it (its hingeAngles unwrap the angles where it has them) and the
// fold amount (0..1) the state was folded toward. Output: the report. Cost: the crossing test
// (a bounding-volume search over the triangles) dominates.
StateReport reportState(const BarHingeModel& model, const SimulationState& state, double amount);

// The static solver's verdict on a state as `curvefold simulate --settle` prints it: "settled in
// N iterations, residual R, energy E (rose in K)", "NOT settled in ...", or, where the rounding
// floor decided (StaticResult::atRoundingFloor), "settled at the rounding floor (residual R,
// floor F) in N iterations, energy E (rose in K)"; K is energyRises(result.history).
std::string settleSummary(const StaticResult& result);

}  // namespace curvefold
