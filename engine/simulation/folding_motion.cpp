#include "engine/simulation/folding_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/simulation/static_solver.hpp"

namespace curvefold {

double foldProgress(const BarHingeModel& model, const std::vector<double>& angles) {
  double along = 0.0, full = 0.0;
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    if (!model.hingeDriven[j]) continue;
    const double weight = model.hingeStiffness[j], target = model.hingeTarget[j];
    along += weight * angles[j] * target;
    full += weight * target * target;
  }
  return full > 0.0 ? along / full : 0.0;
}

FoldingMotion foldingMotion(const BarHingeModel& model, const FoldingMotionOptions& options) {
  const std::size_t hinges = model.hinges.size();
  const std::vector<double> zero = hingeTargets(model, 0.0), full = hingeTargets(model, 1.0);
  FoldingMotion motion;
  motion.amounts.push_back(0.0);
  motion.targets = zero;
  SimulationState state = flatState(model);
  StaticOptions solve;
  solve.predictor = false;
  solve.maxStageDegrees = 180.0;  // one stage: the step is already small
  solve.tolerance = 1e-8;
  solve.maxIterations = 200;
  const double stepRadians = options.stepDegrees * std::numbers::pi / 180.0;
  std::vector<double> goal(hinges);
  for (; motion.steps < options.maxSteps; ++motion.steps) {
    double largest = 0.0;
    for (std::size_t j = 0; j < hinges; ++j)
      if (model.hingeDriven[j])
        largest = std::max(largest, std::abs(full[j] - state.hingeAngles[j]));
    if (largest <= 1e-4) {
      motion.reachedFull = true;
      break;
    }
    const double share = std::min(1.0, stepRadians / largest);
    for (std::size_t j = 0; j < hinges; ++j)
      goal[j] = model.hingeDriven[j]
                    ? state.hingeAngles[j] + share * (full[j] - state.hingeAngles[j])
                    : full[j];
    settleToTargets(model, goal, state, solve);
    const double progress = foldProgress(model, state.hingeAngles);
    // Stalled (no equilibrium measurably nearer the 100% angles), or a hinge pushed past its
    // 100% angle by the others (beyond a flat fold the sheet passes through itself, as a
    // symmetric waterbomb's diagonals would before its midlines close): the rest is linear.
    bool past = false;
    for (std::size_t j = 0; j < hinges; ++j)
      past = past || (model.hingeDriven[j] &&
                      (state.hingeAngles[j] - full[j]) * full[j] > 1e-3 * std::abs(full[j]));
    if (past || !(progress > motion.amounts.back() + 1e-4)) break;
    if (progress >= 1.0 - 1e-4) {  // there: reached when every hinge is within 0.1 degree
      double remaining = 0.0;
      for (std::size_t j = 0; j < hinges; ++j)
        if (model.hingeDriven[j])
          remaining = std::max(remaining, std::abs(full[j] - state.hingeAngles[j]));
      motion.reachedFull = remaining <= 0.1 * std::numbers::pi / 180.0;
      break;
    }
    motion.amounts.push_back(progress);
    for (std::size_t j = 0; j < hinges; ++j)
      motion.targets.push_back(model.hingeDriven[j] ? state.hingeAngles[j] : full[j]);
  }
  motion.amounts.push_back(1.0);
  motion.targets.insert(motion.targets.end(), full.begin(), full.end());
  return motion;
}

void setFoldingMotion(BarHingeModel& model, const FoldingMotion& motion) {
  model.motionAmounts = motion.amounts;
  model.motionTargets = motion.targets;
}

}  // namespace curvefold
