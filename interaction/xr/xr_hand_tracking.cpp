#include "interaction/xr/xr_hand_tracking.hpp"

#include <glm/gtc/quaternion.hpp>

#include "interaction/xr/xr_check.hpp"

namespace curvefold {

XrHandTracking::XrHandTracking(XrInstance instance)
    : createTracker_(xrFunction<PFN_xrCreateHandTrackerEXT>(instance, "xrCreateHandTrackerEXT")),
      destroyTracker_(xrFunction<PFN_xrDestroyHandTrackerEXT>(instance, "xrDestroyHandTrackerEXT")),
      locateJoints_(xrFunction<PFN_xrLocateHandJointsEXT>(instance, "xrLocateHandJointsEXT")) {}

XrHandTracking::~XrHandTracking() {
  detach();
}

void XrHandTracking::attach(XrSession session) {
  for (XrHandEXT hand : {XR_HAND_LEFT_EXT, XR_HAND_RIGHT_EXT}) {
    XrHandTrackerCreateInfoEXT info{XR_TYPE_HAND_TRACKER_CREATE_INFO_EXT};
    info.hand = hand;
    info.handJointSet = XR_HAND_JOINT_SET_DEFAULT_EXT;
    CHECK_XR(createTracker_(session, &info, &trackers_[hand == XR_HAND_LEFT_EXT ? 0 : 1]));
  }
}

void XrHandTracking::detach() {
  for (XrHandTrackerEXT& tracker : trackers_) {
    if (tracker != XR_NULL_HANDLE) destroyTracker_(tracker);
    tracker = XR_NULL_HANDLE;
  }
}

HandJoints XrHandTracking::locate(HandSide side, XrSpace base, XrTime time) const {
  HandJoints hand;
  const XrHandTrackerEXT tracker = trackers_[std::size_t(side)];
  if (tracker == XR_NULL_HANDLE) return hand;
  std::array<XrHandJointLocationEXT, XR_HAND_JOINT_COUNT_EXT> joints{};
  XrHandJointLocationsEXT locations{XR_TYPE_HAND_JOINT_LOCATIONS_EXT};
  locations.jointCount = XR_HAND_JOINT_COUNT_EXT;
  locations.jointLocations = joints.data();
  XrHandJointsLocateInfoEXT info{XR_TYPE_HAND_JOINTS_LOCATE_INFO_EXT};
  info.baseSpace = base;
  info.time = time;
  CHECK_XR(locateJoints_(tracker, &info, &locations));
  if (!locations.isActive) return hand;
  constexpr XrSpaceLocationFlags kValid =
      XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    // A hand with a joint the runtime cannot place is not used at all: half a hand would pinch
    // or close by accident.
    if ((joints[i].locationFlags & kValid) != kValid) return HandJoints{};
    const XrPosef& pose = joints[i].pose;
    hand.joints[i] = {{pose.position.x, pose.position.y, pose.position.z},
                      glm::normalize(glm::dquat(pose.orientation.w, pose.orientation.x,
                                                pose.orientation.y, pose.orientation.z))};
  }
  hand.tracked = true;
  return hand;
}

bool xrSystemTracksHands(XrInstance instance, XrSystemId system) {
  XrSystemHandTrackingPropertiesEXT hands{XR_TYPE_SYSTEM_HAND_TRACKING_PROPERTIES_EXT};
  XrSystemProperties properties{XR_TYPE_SYSTEM_PROPERTIES};
  properties.next = &hands;
  CHECK_XR(xrGetSystemProperties(instance, system, &properties));
  return hands.supportsHandTracking == XR_TRUE;
}

}  // namespace curvefold
