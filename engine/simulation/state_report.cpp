#include "engine/simulation/state_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/simulation/contact.hpp"

namespace curvefold {

StateReport reportState(const BarHingeModel& model, const SimulationState& state, double amount) {
  StateReport report;
  report.strain = edgeStrain(model, state.positions);
  report.angleError = creaseAngleError(model, state.positions, amount, state.hingeAngles);
  for (double s : report.strain) report.largestStrain = std::max(report.largestStrain, std::abs(s));
  for (double a : report.angleError)
    report.largestAngleError = std::max(report.largestAngleError, std::abs(a));
  double sum = 0.0;
  std::size_t creases = 0;
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j]) {
      sum += std::abs(report.angleError[model.hingeEdge[j]]);
      ++creases;
    }
  report.meanAngleError = creases ? sum / static_cast<double>(creases) : 0.0;
  report.crossingPairs = crossingTrianglePairs(model, state.positions);
  const std::vector<double> angles = state.hingeAngles.size() == model.hinges.size()
                                         ? state.hingeAngles
                                         : hingeAngles(model, state.positions);
  constexpr double kHalfDegree = 0.5 * std::numbers::pi / 180.0;
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    if (!model.hingeCrease[j] || model.hingeTarget[j] == 0.0) continue;
    const double along = (model.hingeTarget[j] > 0.0 ? 1.0 : -1.0) * angles[j];
    if (along < -kHalfDegree) ++report.wrongSideCreases;
    if (along > std::numbers::pi + kHalfDegree) ++report.pastFlatCreases;
  }
  return report;
}

std::string settleSummary(const StaticResult& result) {
  char text[200];
  const std::size_t rises = energyRises(result.history);
  if (result.atRoundingFloor)
    std::snprintf(text, sizeof text,
                  "settled at the rounding floor (residual %.1e, floor %.1e) in %zu iterations, "
                  "energy %.6g (rose in %zu)",
                  result.residual, result.roundingFloor, result.iterations, result.energy, rises);
  else
    std::snprintf(text, sizeof text,
                  "%s in %zu iterations, residual %.1e, energy %.6g (rose in %zu)",
                  result.converged ? "settled" : "NOT settled", result.iterations, result.residual,
                  result.energy, rises);
  return text;
}

}  // namespace curvefold
