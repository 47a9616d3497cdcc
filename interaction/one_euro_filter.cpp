#include "interaction/one_euro_filter.hpp"

#include <algorithm>
#include <numbers>

namespace curvefold {

double lowPassSmoothing(double cutoffHz, double dt) {
  const double tau = 1.0 / (2.0 * std::numbers::pi * cutoffHz);
  return 1.0 / (1.0 + tau / dt);
}

glm::dvec3 OneEuroValue<glm::dquat>::change(const glm::dquat& from, const glm::dquat& to) {
  // q and -q are one orientation: the turn between them is none, and the shorter way is taken.
  glm::dquat turn = to * glm::conjugate(from);
  if (turn.w < 0.0) turn = -turn;
  const glm::dvec3 axisSine(turn.x, turn.y, turn.z);
  const double sine = glm::length(axisSine);
  if (sine < 1e-300) return glm::dvec3(0.0);
  const double angle = 2.0 * std::atan2(sine, std::min(1.0, turn.w));
  return axisSine * (angle / sine);
}

glm::dquat OneEuroValue<glm::dquat>::step(const glm::dquat& from, const glm::dquat& to,
                                          double smoothing) {
  // GLM's slerp takes the shorter way, turning toward -to when that is nearer.
  return glm::normalize(glm::slerp(from, to, smoothing));
}

}  // namespace curvefold
