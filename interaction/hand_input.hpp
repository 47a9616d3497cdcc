// Bare hands as an input source (issue 16, docs/design.md 5b), on the standard joints of
// XR_EXT_hand_tracking and no OpenXR types: the dominant hand's pinch point (between the thumb and
// index tips, filtered) is the point, a pinch is select and a closed hand the second hand's grip;
// the non-dominant hand gives the sheet frame (the centre of its rigid part, rigidCentre, turned
// as its palm; both filtered) and a closed hand is the clutch. Taps
// (the thumb on a fingertip) press the buttons (kSheetHandTaps, kPointHandTaps). Pinch, grab and
// tap have hysteresis (InteractionThresholds), so a hand's jitter neither starts nor drops a fold.
// The result is the same InputFrame every other source makes.
#pragma once

#include <array>
#include <optional>
#include <span>

#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"
#include "interaction/one_euro_filter.hpp"

namespace curvefold {

// XR_EXT_hand_tracking's 26 joints, in its order (XrHandJointEXT).
enum class HandJoint : int {
  Palm,
  Wrist,
  ThumbMetacarpal,
  ThumbProximal,
  ThumbDistal,
  ThumbTip,
  IndexMetacarpal,
  IndexProximal,
  IndexIntermediate,
  IndexDistal,
  IndexTip,
  MiddleMetacarpal,
  MiddleProximal,
  MiddleIntermediate,
  MiddleDistal,
  MiddleTip,
  RingMetacarpal,
  RingProximal,
  RingIntermediate,
  RingDistal,
  RingTip,
  LittleMetacarpal,
  LittleProximal,
  LittleIntermediate,
  LittleDistal,
  LittleTip,
};
inline constexpr int kHandJointCount = 26;

static_assert(static_cast<int>(HandJoint::LittleTip) + 1 == kHandJointCount);

// Every joint, in order: the enum's values index it, as they do HandJoints.
inline constexpr std::array<HandJoint, kHandJointCount> kHandJoints = [] {
  std::array<HandJoint, kHandJointCount> joints{};
  for (int i = 0; i < kHandJointCount; ++i) joints[i] = static_cast<HandJoint>(i);
  return joints;
}();

// The fingers, thumb first (the order of their joints in HandJoint).
enum class HandFinger { Thumb, Index, Middle, Ring, Little };
inline constexpr std::array<HandFinger, 5> kHandFingers = {
    HandFinger::Thumb, HandFinger::Index, HandFinger::Middle, HandFinger::Ring, HandFinger::Little};
// The four fingers beside the thumb, index first.
inline constexpr std::array<HandFinger, 4> kFingersButThumb = {
    HandFinger::Index, HandFinger::Middle, HandFinger::Ring, HandFinger::Little};

// A finger's joints are those from its metacarpal (at the wrist) to its tip, in order: metacarpal,
// proximal (the knuckle), intermediate, distal, tip; the thumb has no intermediate joint.
struct FingerJointRange {
  HandJoint metacarpal, tip;
};
inline constexpr FingerJointRange kFingerJointRanges[] = {
    {HandJoint::ThumbMetacarpal, HandJoint::ThumbTip},
    {HandJoint::IndexMetacarpal, HandJoint::IndexTip},
    {HandJoint::MiddleMetacarpal, HandJoint::MiddleTip},
    {HandJoint::RingMetacarpal, HandJoint::RingTip},
    {HandJoint::LittleMetacarpal, HandJoint::LittleTip}};

constexpr std::span<const HandJoint> fingerJoints(HandFinger finger) {
  const FingerJointRange range = kFingerJointRanges[static_cast<std::size_t>(finger)];
  const auto first = static_cast<std::size_t>(range.metacarpal);
  return std::span(kHandJoints).subspan(first, static_cast<std::size_t>(range.tip) - first + 1);
}
constexpr HandJoint metacarpalOf(HandFinger finger) {
  return fingerJoints(finger).front();
}
// The knuckle: the proximal joint, where the finger leaves the palm.
constexpr HandJoint knuckleOf(HandFinger finger) {
  return fingerJoints(finger)[1];
}
constexpr HandJoint tipOf(HandFinger finger) {
  return fingerJoints(finger).back();
}
constexpr bool isFingerTip(HandJoint joint) {
  for (HandFinger finger : kHandFingers)
    if (joint == tipOf(finger)) return true;
  return false;
}

// One hand's joints as a runtime located them (poses in the base space), or untracked. Each joint's
// -Z points along its bone towards the fingertip and +Y out of the back of the hand.
struct HandJoints {
  bool tracked = false;
  std::array<Pose, kHandJointCount> joints;

  const Pose& operator[](HandJoint joint) const { return joints[static_cast<int>(joint)]; }
  Pose& operator[](HandJoint joint) { return joints[static_cast<int>(joint)]; }
};

// A tap: the thumb's tip on this finger's tip presses this button.
struct HandTap {
  HandJoint fingertip;
  Button button;
};
// The non-dominant hand, open: index shows or hides the panel, middle undoes, ring redoes, little
// cancels the fold under way (the dominant hand keeps pinching).
inline constexpr HandTap kSheetHandTaps[] = {{HandJoint::IndexTip, Button::Panel},
                                             {HandJoint::MiddleTip, Button::Undo},
                                             {HandJoint::RingTip, Button::Redo},
                                             {HandJoint::LittleTip, Button::Cancel}};
// The dominant hand, not pinching: middle switches hands.
inline constexpr HandTap kPointHandTaps[] = {{HandJoint::MiddleTip, Button::SwitchHands}};

// Makes input frames from hands' joints, a role at a time (the other may be a controller). Keeps
// each gesture's state between frames (the hysteresis and the filters), so feed it every frame in
// time order, and reset a role whose hand changes (a controller took over, hands switched).
class HandInput {
 public:
  explicit HandInput(const InteractionThresholds& thresholds = {});

  // Fills the frame's point hand and ORs its taps into the buttons (time as given).
  void updatePointHand(const HandJoints& hand, InputFrame& frame);
  // Fills the frame's sheet hand and ORs its taps into the buttons.
  void updateSheetHand(const HandJoints& hand, InputFrame& frame);
  void update(const HandJoints& pointHand, const HandJoints& sheetHand, InputFrame& frame) {
    updatePointHand(pointHand, frame);
    updateSheetHand(sheetHand, frame);
  }
  void resetPointHand();
  void resetSheetHand();

  bool pinched() const { return point_.pinched; }
  bool pointClosed() const { return point_.closed; }
  bool grabbed() const { return sheet_.closed; }
  // The pinch's openness, 0 (tips touching) to 1 (at the release distance or wider), for drawing.
  double pinchOpenness() const { return pinchOpenness_; }

 private:
  struct Gestures {
    bool pinched = false;
    bool closed = false;
    std::array<bool, 4> taps{};
  };
  // Updates the hysteresis of a hand's closing and of its taps, and ORs held taps into `buttons`.
  void updateClosed(const HandJoints& hand, Gestures& gestures) const;
  template <std::size_t N>
  void updateTaps(const HandJoints& hand, const HandTap (&taps)[N], Gestures& gestures,
                  std::uint32_t& buttons) const;

  InteractionThresholds thresholds_;
  OneEuroFilter<glm::dvec3> pinchFilter_, palmFilter_;
  OneEuroFilter<glm::dquat> aimFilter_, palmRotationFilter_;
  Gestures point_, sheet_;
  double pinchOpenness_ = 1.0;
};

// The point of a pinch: halfway between the thumb and index tips.
glm::dvec3 pinchPoint(const HandJoints& hand);
// The distance between the thumb and index tips.
double pinchDistance(const HandJoints& hand);
// How closed a hand is: the mean distance of the index, middle, ring and little tips to the palm.
double fingertipsToPalm(const HandJoints& hand);
// The centre of the hand's rigid part (palm, wrist, metacarpal bases, knuckles), which curling
// fingers do not move: ten joints averaged, so it is steadier than the palm joint alone.
glm::dvec3 rigidCentre(const HandJoints& hand);
// Where a hand points: from the back of the hand (wrist, metacarpal bases) over the knuckles,
// which a pinch does not move.
glm::dvec3 handPointingDirection(const HandJoints& hand);

}  // namespace curvefold
