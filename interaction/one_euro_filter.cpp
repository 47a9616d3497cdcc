#include "interaction/one_euro_filter.hpp"

#include <algorithm>
#include <numbers>

namespace curvefold {

double lowPassSmoothing(double cutoffHz, double dt) {
  const double tau = 1.0 / (2.0 * std::numbers::pi * cutoffHz);
  return 1.0 / (1.0 + tau / dt);
}

double OneEuroValue<glm::dquat>::change(const glm::dquat& from, const glm::dquat& to) {
  // q and -q are one orientation: the angle between them is zero.
  return 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(from, to))));
}

glm::dquat OneEuroValue<glm::dquat>::step(const glm::dquat& from, const glm::dquat& to,
                                          double smoothing) {
  // GLM's slerp takes the shorter way, turning toward -to when that is nearer.
  return glm::normalize(glm::slerp(from, to, smoothing));
}

}  // namespace curvefold
