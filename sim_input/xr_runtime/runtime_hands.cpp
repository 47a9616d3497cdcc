// The simulated OpenXR runtime: XR_EXT_hand_tracking (the specification's chapter on the
// extension). Each hand's 26 joints come from the served frame (made by SimUser::handsFor and
// jittered once per frame); a hand is active only while hands are served, the hand is in the
// frame and the session is focused (input belongs to the focused application).
#include "sim_input/xr_runtime/runtime_state.hpp"

namespace curvefold::simxr {

namespace {

HandTracker& trackerOf(XrHandTrackerEXT handle) {
  HandTracker* tracker = objectOf<HandTracker>(handle);
  if (!tracker || !gInstance || !gInstance->sessions.count(tracker->session))
    fail(XR_ERROR_HANDLE_INVALID);
  return *tracker;
}

// A joint's radius: fingertips are thinner than knuckles; palm and wrist span the hand.
float jointRadius(HandJoint joint) {
  if (joint == HandJoint::Palm || joint == HandJoint::Wrist) return 0.02f;
  return isFingerTip(joint) ? 0.007f : 0.01f;
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL createHandTracker(XrSession handle,
                                                 const XrHandTrackerCreateInfoEXT* info,
                                                 XrHandTrackerEXT* out) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_HAND_TRACKER_CREATE_INFO_EXT);
    if (!out) return XR_ERROR_VALIDATION_FAILURE;
    if (info->hand != XR_HAND_LEFT_EXT && info->hand != XR_HAND_RIGHT_EXT)
      return XR_ERROR_VALIDATION_FAILURE;
    if (info->handJointSet != XR_HAND_JOINT_SET_DEFAULT_EXT) return XR_ERROR_VALIDATION_FAILURE;
    auto* tracker = new HandTracker{&session, info->hand == XR_HAND_LEFT_EXT ? 0 : 1};
    session.handTrackers.insert(tracker);
    *out = handleOf<XrHandTrackerEXT>(tracker);
    log(std::string("hand tracker ") + (tracker->hand == 0 ? "left" : "right"));
    return XR_SUCCESS;
  });
}

void destroyHandTracker(HandTracker* tracker) {
  tracker->session->handTrackers.erase(tracker);
  gHandles.erase(tracker);
  delete tracker;
}

XRAPI_ATTR XrResult XRAPI_CALL destroyHandTrackerEntry(XrHandTrackerEXT handle) {
  return guard([&] {
    destroyHandTracker(&trackerOf(handle));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL locateHandJoints(XrHandTrackerEXT handle,
                                                const XrHandJointsLocateInfoEXT* info,
                                                XrHandJointLocationsEXT* locations) {
  return guard([&] {
    HandTracker& tracker = trackerOf(handle);
    liveSessionOf(reinterpret_cast<XrSession>(tracker.session));
    checkType(info, XR_TYPE_HAND_JOINTS_LOCATE_INFO_EXT);
    checkType(locations, XR_TYPE_HAND_JOINT_LOCATIONS_EXT);
    Space* base = objectOf<Space>(info->baseSpace);
    if (!base) return XR_ERROR_HANDLE_INVALID;
    if (info->time <= 0) return XR_ERROR_TIME_INVALID;
    if (locations->jointCount != XR_HAND_JOINT_COUNT_EXT || !locations->jointLocations)
      return XR_ERROR_VALIDATION_FAILURE;
    XrHandJointVelocitiesEXT* velocities = nullptr;
    for (auto* next = static_cast<XrBaseOutStructure*>(locations->next); next; next = next->next)
      if (next->type == XR_TYPE_HAND_JOINT_VELOCITIES_EXT) {
        velocities = reinterpret_cast<XrHandJointVelocitiesEXT*>(next);
        if (velocities->jointCount != XR_HAND_JOINT_COUNT_EXT || !velocities->jointVelocities)
          return XR_ERROR_VALIDATION_FAILURE;
      }
    Instance& instance = *gInstance;
    const HandJoints& hand = instance.handJoints[tracker.hand];
    bool baseValid = false;
    const Pose worldBase = locate(instance, *base, baseValid);
    const bool active = instance.servingHands && hand.tracked && baseValid &&
                        tracker.session->state == XR_SESSION_STATE_FOCUSED;
    locations->isActive = active ? XR_TRUE : XR_FALSE;
    for (std::uint32_t i = 0; i < XR_HAND_JOINT_COUNT_EXT; ++i) {
      XrHandJointLocationEXT& joint = locations->jointLocations[i];
      joint.radius = jointRadius(kHandJoints[i]);
      joint.locationFlags = 0;
      joint.pose = toXr(Pose{});
      if (active) {
        joint.pose = toXr(worldBase.inverse() * hand.joints[i]);
        joint.locationFlags =
            XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
            XR_SPACE_LOCATION_POSITION_TRACKED_BIT | XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
      }
      // The simulated hands report no velocities (runtimes may not).
      if (velocities) velocities->jointVelocities[i].velocityFlags = 0;
    }
    return XR_SUCCESS;
  });
}

}  // namespace curvefold::simxr
