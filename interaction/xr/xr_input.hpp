// The OpenXR input source (docs/design.md 5), in the manner of hello_xr: one action set with an
// action per XrControl (interaction/xr_controls.hpp), each on both hands' subaction paths, bindings
// suggested once for every profile in the controls table, the action set attached to each
// session, and everything polled once a frame into the InputFrame every other source produces.
//
// Roles follow the handedness the interaction core has now: the non-dominant hand's grip pose and
// squeeze hold the sheet; the dominant hand's tip (kXrTipOffset ahead of its aim pose) and trigger
// fold; undo and redo are read on the non-dominant hand, cancel on the dominant one, switching
// hands on either. Poses are located at the frame's predicted display time.
//
// Bare hands (XR_EXT_hand_tracking, docs/design.md 5b): a role whose hand holds no located
// controller is driven by that hand's joints through HandInput (with `--hands`, always), so the
// controllers can be put down and picked up again mid-session.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <openxr/openxr.h>

#include "interaction/hand_input.hpp"
#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"
#include "interaction/xr/xr_hand_tracking.hpp"
#include "interaction/xr_controls.hpp"

namespace curvefold {

// What drives a role: a controller's actions or a bare hand's joints.
enum class XrHandSource { Controller, Hand };

// The hand that has the role for `handedness` (the dominant hand).
HandSide sheetHandSide(HandSide handedness);
HandSide pointHandSide(HandSide handedness);

// How a profile's suggested bindings went: a runtime that does not know a profile refuses it,
// which is not an error for us (another profile serves).
struct XrBindingSuggestion {
  std::string profile;
  XrResult result = XR_SUCCESS;
};

class XrInput {
 public:
  // Creates the action set and its actions and suggests the bindings of every profile; with
  // `handTracking` (the instance enabled XR_EXT_hand_tracking) loads its functions, and with
  // `handsOnly` drives both roles by hands. Throws XrError.
  explicit XrInput(XrInstance instance, bool handTracking = false, bool handsOnly = false,
                   const InteractionThresholds& thresholds = {});
  ~XrInput();
  XrInput(const XrInput&) = delete;
  XrInput& operator=(const XrInput&) = delete;

  // Per session: attaches the action set and creates the hands' action spaces, and the hand
  // trackers when the system tracks hands.
  void attach(XrSession session, bool tracksHands = false);
  // Before the session is destroyed: drops its action spaces.
  void detach();

  // Syncs the actions and reads both hands at `time` into a frame (time in seconds given by the
  // caller). Hands that are not located are untracked. Returns false, with an empty frame, when
  // the session is not focused (input then belongs to another application).
  bool poll(XrSpace base, XrTime time, HandSide handedness, double seconds, InputFrame& frame);
  // The point hand's aim pose at the last poll (none when not located): the frame carries only its
  // tip, the headset draws the controller along it.
  const std::optional<Pose>& pointAim() const { return pointAim_; }
  // Haptic pulses on the hands in their roles.
  void applyHaptics(std::span<const HapticPulse> pulses, HandSide handedness);

  // The current interaction profile of each hand ("" when none), from
  // xrGetCurrentInteractionProfile.
  std::array<std::string, 2> currentProfiles() const;
  const std::vector<XrBindingSuggestion>& suggestions() const { return suggestions_; }

  // At the last poll: what drove each role, and the hands' joints as located (untracked when not).
  XrHandSource sheetSource() const { return sheetSource_; }
  XrHandSource pointSource() const { return pointSource_; }
  bool usesHands() const {
    return sheetSource_ == XrHandSource::Hand || pointSource_ == XrHandSource::Hand;
  }
  const HandJoints& sheetJoints() const { return sheetJoints_; }
  const HandJoints& pointJoints() const { return pointJoints_; }
  const HandInput& handInput() const { return hands_; }

 private:
  XrPath path(const std::string& text) const;
  XrAction action(XrControl control) const { return actions_.at(control); }
  float floatState(XrControl control, HandSide hand) const;
  std::optional<Pose> pointAim_;
  bool booleanState(XrControl control, XrPath subaction) const;

  XrInstance instance_ = XR_NULL_HANDLE;
  XrSession session_ = XR_NULL_HANDLE;
  XrActionSet actionSet_ = XR_NULL_HANDLE;
  std::map<XrControl, XrAction> actions_;
  std::array<XrPath, 2> handPaths_{};
  std::array<XrSpace, 2> gripSpaces_{XR_NULL_HANDLE, XR_NULL_HANDLE};
  std::array<XrSpace, 2> aimSpaces_{XR_NULL_HANDLE, XR_NULL_HANDLE};
  std::vector<XrBindingSuggestion> suggestions_;

  std::unique_ptr<XrHandTracking> handTracking_;  // none without the extension
  bool tracksHands_ = false;
  bool handsOnly_ = false;
  HandInput hands_;
  HandSide handedness_ = HandSide::Right;
  XrHandSource sheetSource_ = XrHandSource::Controller, pointSource_ = XrHandSource::Controller;
  HandJoints sheetJoints_, pointJoints_;
};

}  // namespace curvefold
