// The OpenXR input source (docs/design.md 5), in the manner of hello_xr: one action set with an
// action per XrControl (interaction/xr_controls.hpp), each on both hands' subaction paths, bindings
// suggested once for every profile in the controls table, the action set attached to each
// session, and everything polled once a frame into the InputFrame every other source produces.
//
// Roles follow the handedness the interaction core has now: the non-dominant hand's grip pose and
// squeeze hold the sheet; the dominant hand's tip (kXrTipOffset ahead of its aim pose) and trigger
// fold; undo and redo are read on the non-dominant hand, cancel on the dominant one, switching
// hands on either. Poses are located at the frame's predicted display time.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <openxr/openxr.h>

#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"
#include "interaction/xr_controls.hpp"

namespace curvefold {

enum class XrHandSide { Left = 0, Right = 1 };

// The hand that has the role for `handedness`.
XrHandSide sheetHandSide(Handedness handedness);
XrHandSide pointHandSide(Handedness handedness);

// How a profile's suggested bindings went: a runtime that does not know a profile refuses it,
// which is not an error for us (another profile serves).
struct XrBindingSuggestion {
  std::string profile;
  XrResult result = XR_SUCCESS;
};

class XrInput {
 public:
  // Creates the action set and its actions and suggests the bindings of every profile. Throws
  // XrError.
  explicit XrInput(XrInstance instance);
  ~XrInput();
  XrInput(const XrInput&) = delete;
  XrInput& operator=(const XrInput&) = delete;

  // Per session: attaches the action set and creates the hands' action spaces.
  void attach(XrSession session);
  // Before the session is destroyed: drops its action spaces.
  void detach();

  // Syncs the actions and reads both hands at `time` into a frame (time in seconds given by the
  // caller). Hands that are not located are untracked. Returns false, with an empty frame, when
  // the session is not focused (input then belongs to another application).
  bool poll(XrSpace base, XrTime time, Handedness handedness, double seconds, InputFrame& frame);
  // The point hand's aim pose at the last poll (none when not located): the frame carries only its
  // tip, the headset draws the controller along it.
  const std::optional<Pose>& pointAim() const { return pointAim_; }
  // Haptic pulses on the hands in their roles.
  void applyHaptics(std::span<const HapticPulse> pulses, Handedness handedness);

  // The current interaction profile of each hand ("" when none), from
  // xrGetCurrentInteractionProfile.
  std::array<std::string, 2> currentProfiles() const;
  const std::vector<XrBindingSuggestion>& suggestions() const { return suggestions_; }

 private:
  XrPath path(const std::string& text) const;
  XrAction action(XrControl control) const { return actions_.at(control); }
  float floatState(XrControl control, XrHandSide hand) const;
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
};

}  // namespace curvefold
