// Bare hands as an input source (issue 16), on the standard joints of XR_EXT_hand_tracking and no
// OpenXR types: the dominant hand's pinch point (between the thumb and index tips, filtered) is the
// point and a pinch is select; the non-dominant hand's palm is the sheet frame and a closed hand is
// the clutch. Pinch and grab have hysteresis (InteractionThresholds), so a hand's jitter neither
// starts nor drops a fold. The result is the same InputFrame every other source makes.
#pragma once

#include <array>
#include <optional>

#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"

namespace curvefold {

// XR_EXT_hand_tracking's 26 joints, in its order (XrHandJointEXT).
enum class HandJoint : int {
  Palm = 0,
  Wrist = 1,
  ThumbMetacarpal = 2,
  ThumbTip = 5,
  IndexMetacarpal = 6,
  IndexProximal = 7,
  IndexTip = 10,
  MiddleMetacarpal = 11,
  MiddleTip = 15,
  RingTip = 20,
  LittleTip = 25,
};
inline constexpr int kHandJointCount = 26;

// One hand's joints as a runtime located them (poses in the base space), or untracked.
struct HandJoints {
  bool tracked = false;
  std::array<Pose, kHandJointCount> joints;

  const Pose& operator[](HandJoint joint) const { return joints[static_cast<int>(joint)]; }
  Pose& operator[](HandJoint joint) { return joints[static_cast<int>(joint)]; }
};

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

// Makes input frames from both hands' joints. Keeps each gesture's state between frames (the
// hysteresis and the filter), so feed it every frame in time order.
class HandInput {
 public:
  explicit HandInput(const InteractionThresholds& thresholds = {});

  // Fills the frame's hands (time and buttons stay as given) from the dominant (point) and
  // non-dominant (sheet) hands' joints.
  void update(const HandJoints& pointHand, const HandJoints& sheetHand, InputFrame& frame);

  bool pinched() const { return pinched_; }
  bool grabbed() const { return grabbed_; }

 private:
  InteractionThresholds thresholds_;
  OneEuroFilter pinchFilter_;
  bool pinched_ = false;
  bool grabbed_ = false;
};

// The point of a pinch: halfway between the thumb and index tips.
glm::dvec3 pinchPoint(const HandJoints& hand);
// The distance between the thumb and index tips.
double pinchDistance(const HandJoints& hand);
// How closed a hand is: the mean distance of the index, middle, ring and little tips to the palm.
double fingertipsToPalm(const HandJoints& hand);

}  // namespace curvefold
