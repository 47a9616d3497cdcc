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

#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"

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

// The One Euro filter (Casiez, Roussel and Vogel, CHI 2012) on a point: a low-pass filter whose
// cutoff rises with speed, so a hand at rest is steady and a moving hand is not left behind.
class OneEuroFilter {
 public:
  OneEuroFilter(double minCutoff, double beta, double derivativeCutoff = 1.0)
      : minCutoff_(minCutoff), beta_(beta), derivativeCutoff_(derivativeCutoff) {}

  // The filtered point for a sample at `time` (seconds, never going back).
  glm::dvec3 filter(const glm::dvec3& sample, double time);
  void reset() { last_.reset(); }

 private:
  double minCutoff_, beta_, derivativeCutoff_;
  std::optional<glm::dvec3> last_;
  glm::dvec3 lastDerivative_{0.0};
  double lastTime_ = 0.0;
};

// The same filter on an orientation: the step towards each sample is a slerp, its speed the angle
// turned per second.
class OneEuroRotationFilter {
 public:
  OneEuroRotationFilter(double minCutoff, double beta, double derivativeCutoff = 1.0)
      : minCutoff_(minCutoff), beta_(beta), derivativeCutoff_(derivativeCutoff) {}

  glm::dquat filter(const glm::dquat& sample, double time);
  void reset() { last_.reset(); }

 private:
  double minCutoff_, beta_, derivativeCutoff_;
  std::optional<glm::dquat> last_;
  double lastSpeed_ = 0.0;
  double lastTime_ = 0.0;
};

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
  OneEuroFilter pinchFilter_, palmFilter_;
  OneEuroRotationFilter aimFilter_, palmRotationFilter_;
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
