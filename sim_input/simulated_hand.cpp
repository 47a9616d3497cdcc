#include "sim_input/simulated_hand.hpp"

#include <array>
#include <cmath>
#include <span>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

namespace curvefold {

namespace {

using J = HandJoint;

struct Finger {
  HandFinger which;    // not the thumb, which is placed on its own
  double across;       // the knuckle's place across the hand (right hand, +X away from the thumb)
  double scale;        // its length against the index finger's
  glm::dvec3 contact;  // where its tip meets the thumb's in a tap
};

// A right hand in the palm's frame (metres). The left hand is its mirror image across X.
constexpr std::array<Finger, 4> kFingers = {{
    {HandFinger::Index, -0.021, 1.0, {-0.045, -0.035, -0.075}},
    {HandFinger::Middle, 0.0, 1.08, {-0.03, -0.045, -0.065}},
    {HandFinger::Ring, 0.019, 1.0, {-0.015, -0.05, -0.055}},
    {HandFinger::Little, 0.036, 0.82, {-0.002, -0.05, -0.045}},
}};
constexpr glm::dvec3 kWrist{0.0, 0.0, 0.05};
constexpr double kKnuckles = -0.045;                 // the knuckles' Z
constexpr double kBones[3] = {0.045, 0.027, 0.022};  // proximal, intermediate, distal phalanges
constexpr double kOpenCurl[3] = {0.08, 0.08, 0.06};  // radians at each knuckle, curling palmwards
constexpr double kClosedCurl[3] = {1.5, 1.6, 1.0};
constexpr double kTipGap = 0.003;  // between touching tips (skin and tracking)

// Positions in the palm's frame, right hand.
std::array<glm::dvec3, kHandJointCount> rightHandPositions(const HandPosture& posture) {
  std::array<glm::dvec3, kHandJointCount> p{};
  auto at = [&](J j) -> glm::dvec3& { return p[static_cast<int>(j)]; };
  at(J::Palm) = glm::dvec3(0.0);
  at(J::Wrist) = kWrist;
  const bool closed = posture.shape == HandShape::Closed;
  std::optional<J> touching = posture.tap;
  if (posture.shape == HandShape::Pinch) touching = J::IndexTip;
  if (closed) touching.reset();

  std::optional<glm::dvec3> contact;
  for (const Finger& finger : kFingers) {
    // Metacarpal, knuckle, then the three joints the phalanges end at: intermediate, distal, tip.
    const std::span<const J> chain = fingerJoints(finger.which);
    const glm::dvec3 knuckle(finger.across, 0.0, kKnuckles);
    at(metacarpalOf(finger.which)) = glm::dvec3(0.4 * finger.across, 0.0, 0.045);
    at(knuckleOf(finger.which)) = knuckle;
    if (touching && *touching == chain.back()) {
      // Bent to meet the thumb: the middle joints between the knuckle and the contact, sagging.
      contact = finger.contact;
      const glm::dvec3 toward = finger.contact - knuckle;
      at(chain[2]) = knuckle + 0.5 * toward + glm::dvec3(0.0, -0.012, 0.0);
      at(chain[3]) = knuckle + 0.8 * toward + glm::dvec3(0.0, -0.006, 0.0);
      at(tipOf(finger.which)) = finger.contact + glm::dvec3(0.5 * kTipGap, 0.0, 0.0);
      continue;
    }
    const double* curl = closed ? kClosedCurl : kOpenCurl;
    glm::dvec3 q = knuckle;
    double angle = 0.0;
    for (int bone = 0; bone < 3; ++bone) {
      angle += curl[bone];
      q += finger.scale * kBones[bone] * glm::dvec3(0.0, -std::sin(angle), -std::cos(angle));
      at(chain[2 + bone]) = q;
    }
  }
  at(J::ThumbMetacarpal) = {-0.025, -0.01, 0.035};
  at(J::ThumbProximal) = {-0.045, -0.015, 0.005};
  if (contact) {
    at(J::ThumbTip) = *contact - glm::dvec3(0.5 * kTipGap, 0.0, 0.0);
    at(J::ThumbDistal) = at(J::ThumbProximal) + 0.6 * (*contact - at(J::ThumbProximal)) +
                         glm::dvec3(-0.005, 0.0, 0.0);
  } else if (closed) {
    // Across the curled fingers' middle phalanges.
    at(J::ThumbDistal) = {-0.03, -0.035, -0.03};
    at(J::ThumbTip) = {-0.005, -0.035, -0.045};
  } else {
    at(J::ThumbDistal) = {-0.058, -0.02, -0.025};
    at(J::ThumbTip) = {-0.065, -0.022, -0.048};
  }
  return p;
}

// A joint's orientation: -Z along its bone towards the fingertip, +Y out of the back of the hand.
glm::dquat boneOrientation(const glm::dvec3& along) {
  const glm::dvec3 z = -glm::normalize(along);
  glm::dvec3 up(0.0, 1.0, 0.0);
  if (std::abs(glm::dot(up, z)) > 0.9) up = glm::dvec3(0.0, 0.0, 1.0);  // a finger curled down
  const glm::dvec3 y = glm::normalize(up - glm::dot(up, z) * z);
  const glm::dvec3 x = glm::cross(y, z);
  return glm::normalize(glm::quat_cast(glm::dmat3(x, y, z)));
}

HandJoints handInPalmFrame(HandSide side, const HandPosture& posture) {
  std::array<glm::dvec3, kHandJointCount> p = rightHandPositions(posture);
  if (side == HandSide::Left)
    for (glm::dvec3& position : p) position.x = -position.x;
  HandJoints hand;
  hand.tracked = true;
  for (int i = 0; i < kHandJointCount; ++i) hand.joints[i].position = p[i];
  // Palm and wrist share the palm's frame; each other joint looks along its bone (a tip along
  // the bone before it).
  for (HandFinger finger : kHandFingers) {
    const std::span<const J> chain = fingerJoints(finger);
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const bool tip = k + 1 == chain.size();
      const J next = tip ? chain[k] : chain[k + 1];
      const J from = tip ? chain[k - 1] : chain[k];
      hand[chain[k]].orientation = boneOrientation(hand[next].position - hand[from].position);
    }
  }
  return hand;
}

HandJoints placed(const HandJoints& local, const Pose& palm) {
  HandJoints hand = local;
  for (Pose& joint : hand.joints) joint = palm * joint;
  return hand;
}

}  // namespace

HandJoints simulatedHand(const Pose& palm, HandSide side, const HandPosture& posture) {
  return placed(handInPalmFrame(side, posture), palm);
}

HandJoints simulatedPointingHand(const glm::dvec3& point, const glm::dquat& aim, HandSide side,
                                 const HandPosture& posture) {
  const HandJoints local = handInPalmFrame(side, posture);
  // Turned so that the hand's pointing direction is the aim's -Z.
  const glm::dquat turn =
      aim * glm::dquat(handPointingDirection(local), glm::dvec3(0.0, 0.0, -1.0));
  return placed(local, {point - turn * pinchPoint(local), glm::normalize(turn)});
}

void jitterJoints(HandJoints& hand, double radius, std::mt19937_64& random) {
  if (!(radius > 0.0)) return;
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Pose& joint : hand.joints) {
    // One draw per statement: the order in which a call's arguments are evaluated is unspecified
    // (GCC went right to left, clang left to right), so dvec3(unit(random), ...) jittered the
    // hands differently in the two compilers' builds (issue 40, 4).
    glm::dvec3 offset;
    do {
      offset.x = unit(random);
      offset.y = unit(random);
      offset.z = unit(random);
    } while (glm::dot(offset, offset) > 1.0);
    joint.position += radius * offset;
  }
}

HandPosture sheetHandPosture(const InputFrame& frame) {
  HandPosture posture;
  if (frame.sheetHand.clutch >= 0.5) {
    posture.shape = HandShape::Closed;
    return posture;
  }
  for (const HandTap& tap : kSheetHandTaps)
    if (frame.held(tap.button)) {
      posture.tap = tap.fingertip;
      break;
    }
  return posture;
}

HandPosture pointHandPosture(const InputFrame& frame) {
  HandPosture posture;
  if (frame.pointHand.select >= 0.5) {
    posture.shape = HandShape::Pinch;
  } else if (frame.pointHand.grip >= 0.5) {
    posture.shape = HandShape::Closed;
  } else {
    for (const HandTap& tap : kPointHandTaps)
      if (frame.held(tap.button)) {
        posture.tap = tap.fingertip;
        break;
      }
  }
  return posture;
}

}  // namespace curvefold
