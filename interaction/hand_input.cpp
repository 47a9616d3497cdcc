#include "interaction/hand_input.hpp"

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace curvefold {

glm::dvec3 pinchPoint(const HandJoints& hand) {
  return 0.5 * (hand[HandJoint::ThumbTip].position + hand[HandJoint::IndexTip].position);
}

double pinchDistance(const HandJoints& hand) {
  return glm::distance(hand[HandJoint::ThumbTip].position, hand[HandJoint::IndexTip].position);
}

double fingertipsToPalm(const HandJoints& hand) {
  const glm::dvec3 palm = hand[HandJoint::Palm].position;
  double sum = 0.0;
  for (HandFinger finger : kFingersButThumb)
    sum += glm::distance(hand[tipOf(finger)].position, palm);
  return sum / 4.0;
}

glm::dvec3 rigidCentre(const HandJoints& hand) {
  glm::dvec3 sum = hand[HandJoint::Palm].position + hand[HandJoint::Wrist].position;
  for (HandFinger finger : kFingersButThumb) {
    sum += hand[metacarpalOf(finger)].position;
    sum += hand[knuckleOf(finger)].position;
  }
  return sum / 10.0;
}

glm::dvec3 handPointingDirection(const HandJoints& hand) {
  // From the back of the hand (wrist and metacarpal bases) to the knuckles: nine joints a pinch
  // does not move, averaged so one joint's jitter turns the ray less.
  glm::dvec3 back = hand[HandJoint::Wrist].position, knuckles(0.0);
  for (HandFinger finger : kFingersButThumb) {
    back += hand[metacarpalOf(finger)].position;
    knuckles += hand[knuckleOf(finger)].position;
  }
  const glm::dvec3 along = 0.25 * knuckles - 0.2 * back;
  const double length = glm::length(along);
  return length > kShortestPointingSpan ? along / length : glm::dvec3(0.0);
}

HandInput::HandInput(const InteractionThresholds& thresholds)
    : thresholds_(thresholds),
      pinchFilter_({thresholds_.handFilterMinCutoff, thresholds_.handFilterBeta,
                    thresholds_.handFilterDerivativeCutoff}),
      palmFilter_({thresholds_.handFilterMinCutoff, thresholds_.handFilterBeta,
                   thresholds_.handFilterDerivativeCutoff}),
      aimFilter_({thresholds_.handAimFilterMinCutoff, thresholds_.handAimFilterBeta,
                  thresholds_.handFilterDerivativeCutoff}),
      palmRotationFilter_({thresholds_.handRotationFilterMinCutoff,
                           thresholds_.handRotationFilterBeta,
                           thresholds_.handFilterDerivativeCutoff}) {}

void HandInput::updateClosed(const HandJoints& hand, Gestures& gestures) const {
  const double curl = fingertipsToPalm(hand);
  if (gestures.closed && curl >= thresholds_.handOpenAboveMetres) gestures.closed = false;
  if (!gestures.closed && curl <= thresholds_.handClosedBelowMetres) gestures.closed = true;
}

template <std::size_t N>
void HandInput::updateTaps(const HandJoints& hand, const HandTap (&taps)[N], Gestures& gestures,
                           std::uint32_t& buttons) const {
  static_assert(N <= std::tuple_size_v<decltype(gestures.taps)>);
  const glm::dvec3 thumb = hand[HandJoint::ThumbTip].position;
  // A closed hand's thumb lies on its fingers: no taps then, and those held end.
  std::optional<std::size_t> nearest;
  double nearestDistance = 0.0;
  for (std::size_t i = 0; i < N; ++i) {
    const double distance = glm::distance(thumb, hand[taps[i].fingertip].position);
    if (gestures.taps[i] && (distance >= thresholds_.pinchRelease || gestures.closed))
      gestures.taps[i] = false;
    if (!nearest || distance < nearestDistance) {
      nearest = i;
      nearestDistance = distance;
    }
  }
  // Only the fingertip nearest the thumb starts a tap, and only with no tap held.
  const bool anyHeld =
      std::find(gestures.taps.begin(), gestures.taps.end(), true) != gestures.taps.end();
  if (nearest && !anyHeld && !gestures.closed && nearestDistance <= thresholds_.pinchPress)
    gestures.taps[*nearest] = true;
  for (std::size_t i = 0; i < N; ++i)
    if (gestures.taps[i]) buttons |= static_cast<std::uint32_t>(taps[i].button);
}

void HandInput::updatePointHand(const HandJoints& hand, InputFrame& frame) {
  frame.pointHand.tracked = hand.tracked;
  if (!hand.tracked) {
    // A lost hand keeps its pinch (as a controller's trigger would be unknown): the core holds a
    // drag while its hand is untracked. The filters start again where the hand returns.
    pinchFilter_.reset();
    aimFilter_.reset();
    frame.pointHand.select = point_.pinched ? 1.0 : 0.0;
    return;
  }
  updateClosed(hand, point_);
  const double distance = pinchDistance(hand);
  if (point_.pinched && distance >= thresholds_.pinchRelease) point_.pinched = false;
  // A fist is not a pinch: a pinch starts from a hand that is not closed (and, once started,
  // holds if the other fingers curl).
  if (!point_.pinched && !point_.closed && distance <= thresholds_.pinchPress)
    point_.pinched = true;
  pinchOpenness_ = std::clamp(
      (distance - thresholds_.pinchPress) / (thresholds_.pinchRelease - thresholds_.pinchPress),
      0.0, 1.0);
  frame.pointHand.position = pinchFilter_.filter(pinchPoint(hand), frame.time);
  frame.pointHand.select = point_.pinched ? 1.0 : 0.0;
  frame.pointHand.grip = point_.closed && !point_.pinched ? 1.0 : 0.0;
  const glm::dvec3 pointing = handPointingDirection(hand);
  if (pointing != glm::dvec3(0.0))
    frame.pointHand.aim = aimFilter_.filter(
        glm::normalize(glm::dquat(glm::dvec3(0.0, 0.0, -1.0), pointing)), frame.time);
  if (point_.pinched) {
    point_.taps.fill(false);  // the thumb is busy
  } else {
    updateTaps(hand, kPointHandTaps, point_, frame.buttons);
  }
}

void HandInput::updateSheetHand(const HandJoints& hand, InputFrame& frame) {
  frame.sheetHand.tracked = hand.tracked;
  if (!hand.tracked) {
    palmFilter_.reset();
    palmRotationFilter_.reset();
    sheet_.taps.fill(false);
    frame.sheetHand.clutch = sheet_.closed ? 1.0 : 0.0;
    return;
  }
  updateClosed(hand, sheet_);
  frame.sheetHand.pose = {
      palmFilter_.filter(rigidCentre(hand), frame.time),
      palmRotationFilter_.filter(hand[HandJoint::Palm].orientation, frame.time)};
  frame.sheetHand.clutch = sheet_.closed ? 1.0 : 0.0;
  updateTaps(hand, kSheetHandTaps, sheet_, frame.buttons);
}

void HandInput::resetPointHand() {
  point_ = {};
  pinchFilter_.reset();
  aimFilter_.reset();
  pinchOpenness_ = 1.0;
}

void HandInput::resetSheetHand() {
  sheet_ = {};
  palmFilter_.reset();
  palmRotationFilter_.reset();
}

}  // namespace curvefold
