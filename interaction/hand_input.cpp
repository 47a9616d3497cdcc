#include "interaction/hand_input.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace curvefold {

namespace {

// The smoothing factor of a first-order low-pass filter with this cutoff, for a step of dt.
double smoothing(double cutoffHz, double dt) {
  const double tau = 1.0 / (2.0 * std::numbers::pi * cutoffHz);
  return 1.0 / (1.0 + tau / dt);
}

}  // namespace

glm::dvec3 OneEuroFilter::filter(const glm::dvec3& sample, double time) {
  if (!last_) {
    last_ = sample;
    lastDerivative_ = glm::dvec3(0.0);
    lastTime_ = time;
    return sample;
  }
  const double dt = time - lastTime_;
  if (!(dt > 0.0)) return *last_;  // the same instant again: nothing new to smooth
  lastTime_ = time;
  const glm::dvec3 derivative = (sample - *last_) / dt;
  lastDerivative_ += smoothing(derivativeCutoff_, dt) * (derivative - lastDerivative_);
  const double cutoff = minCutoff_ + beta_ * glm::length(lastDerivative_);
  *last_ += smoothing(cutoff, dt) * (sample - *last_);
  return *last_;
}

glm::dvec3 pinchPoint(const HandJoints& hand) {
  return 0.5 * (hand[HandJoint::ThumbTip].position + hand[HandJoint::IndexTip].position);
}

double pinchDistance(const HandJoints& hand) {
  return glm::distance(hand[HandJoint::ThumbTip].position, hand[HandJoint::IndexTip].position);
}

double fingertipsToPalm(const HandJoints& hand) {
  const glm::dvec3 palm = hand[HandJoint::Palm].position;
  double sum = 0.0;
  for (HandJoint tip :
       {HandJoint::IndexTip, HandJoint::MiddleTip, HandJoint::RingTip, HandJoint::LittleTip})
    sum += glm::distance(hand[tip].position, palm);
  return sum / 4.0;
}

HandInput::HandInput(const InteractionThresholds& thresholds)
    : thresholds_(thresholds),
      pinchFilter_(thresholds.pinchFilterMinCutoff, thresholds.pinchFilterBeta) {}

void HandInput::update(const HandJoints& pointHand, const HandJoints& sheetHand,
                       InputFrame& frame) {
  // Point hand: the filtered pinch point, select while pinched, aim along the index finger.
  frame.pointHand.tracked = pointHand.tracked;
  if (pointHand.tracked) {
    const double distance = pinchDistance(pointHand);
    if (pinched_ && distance >= thresholds_.pinchRelease) pinched_ = false;
    if (!pinched_ && distance <= thresholds_.pinchPress) pinched_ = true;
    frame.pointHand.position = pinchFilter_.filter(pinchPoint(pointHand), frame.time);
    frame.pointHand.select = pinched_ ? 1.0 : 0.0;
    const glm::dvec3 along =
        pointHand[HandJoint::IndexTip].position - pointHand[HandJoint::IndexProximal].position;
    if (glm::length(along) > 1e-6)
      frame.pointHand.aim =
          glm::normalize(glm::dquat(glm::dvec3(0.0, 0.0, -1.0), glm::normalize(along)));
  } else {
    // A lost hand keeps its pinch state (as a controller's trigger would be unknown): the core
    // holds a drag while its hand is untracked. The filter starts again where the hand returns.
    pinchFilter_.reset();
  }
  // Sheet hand: the palm's pose, the clutch while the hand is closed.
  frame.sheetHand.tracked = sheetHand.tracked;
  if (sheetHand.tracked) {
    const double curl = fingertipsToPalm(sheetHand);
    if (grabbed_ && curl >= thresholds_.grabRelease) grabbed_ = false;
    if (!grabbed_ && curl <= thresholds_.grabPress) grabbed_ = true;
    frame.sheetHand.pose = sheetHand[HandJoint::Palm];
    frame.sheetHand.clutch = grabbed_ ? 1.0 : 0.0;
  }
}

}  // namespace curvefold
