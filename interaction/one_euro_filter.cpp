#include "interaction/one_euro_filter.hpp"

#include <algorithm>
#include <numbers>

namespace curvefold {

double lowPassSmoothing(double cutoffHz, double dt) {
  const double tau = 1.0 / (2.0 * std::numbers::pi * cutoffHz);
  return 1.0 / (1.0 + tau / dt);
}

namespace {

// q and -q are one orientation: `to` or its negation, whichever is nearer `from`.
glm::dquat nearerSign(const glm::dquat& from, const glm::dquat& to) {
  return glm::dot(from, to) < 0.0 ? -to : to;
}

}  // namespace

double OneEuroValue<glm::dquat>::change(const glm::dquat& from, const glm::dquat& to) {
  return 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(from, nearerSign(from, to)))));
}

glm::dquat OneEuroValue<glm::dquat>::step(const glm::dquat& from, const glm::dquat& to,
                                          double smoothing) {
  return glm::normalize(glm::slerp(from, nearerSign(from, to), smoothing));
}

}  // namespace curvefold
