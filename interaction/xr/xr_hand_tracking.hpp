// Bare hands through XR_EXT_hand_tracking (docs/design.md 5b): a tracker per hand for each session
// and both hands' 26 joints located each frame into HandJoints (interaction/hand_input.hpp), which
// HandInput turns into the input frame. The standard extension only, no vendor ones.
#pragma once

#include <array>

#include <openxr/openxr.h>

#include "interaction/hand_input.hpp"
#include "interaction/hand_side.hpp"

namespace curvefold {

class XrHandTracking {
 public:
  // Loads the extension's functions; the instance must have enabled XR_EXT_hand_tracking.
  // Throws XrError.
  explicit XrHandTracking(XrInstance instance);
  ~XrHandTracking();
  XrHandTracking(const XrHandTracking&) = delete;
  XrHandTracking& operator=(const XrHandTracking&) = delete;

  // Per session: creates both hands' trackers.
  void attach(XrSession session);
  // Before the session is destroyed: destroys them.
  void detach();

  // A hand's joints at `time` in `base`; untracked when the runtime does not track it now (no
  // hand in view, a controller held, the session not focused).
  HandJoints locate(HandSide side, XrSpace base, XrTime time) const;

 private:
  PFN_xrCreateHandTrackerEXT createTracker_ = nullptr;
  PFN_xrDestroyHandTrackerEXT destroyTracker_ = nullptr;
  PFN_xrLocateHandJointsEXT locateJoints_ = nullptr;
  std::array<XrHandTrackerEXT, 2> trackers_{XR_NULL_HANDLE, XR_NULL_HANDLE};
};

// Whether the system tracks hands (XrSystemHandTrackingPropertiesEXT); the instance must have
// enabled XR_EXT_hand_tracking.
bool xrSystemTracksHands(XrInstance instance, XrSystemId system);

}  // namespace curvefold
