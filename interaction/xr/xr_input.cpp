#include "interaction/xr/xr_input.hpp"

#include <algorithm>
#include <cstring>

#include <glm/gtc/quaternion.hpp>

#include "interaction/xr/xr_check.hpp"

namespace curvefold {

namespace {

struct ActionInfo {
  XrControl control;
  const char* name;
  const char* localized;
  XrActionType type;
};

constexpr ActionInfo kActions[] = {
    {XrControl::GripPose, "grip_pose", "Hand grip pose", XR_ACTION_TYPE_POSE_INPUT},
    {XrControl::AimPose, "aim_pose", "Hand aim pose", XR_ACTION_TYPE_POSE_INPUT},
    {XrControl::Clutch, "clutch", "Hold the sheet", XR_ACTION_TYPE_FLOAT_INPUT},
    {XrControl::Select, "select", "Grab and fold", XR_ACTION_TYPE_FLOAT_INPUT},
    {XrControl::Cancel, "cancel", "Cancel the fold", XR_ACTION_TYPE_BOOLEAN_INPUT},
    {XrControl::Undo, "undo", "Undo", XR_ACTION_TYPE_BOOLEAN_INPUT},
    {XrControl::Redo, "redo", "Redo", XR_ACTION_TYPE_BOOLEAN_INPUT},
    {XrControl::SwitchHands, "switch_hands", "Switch hands", XR_ACTION_TYPE_BOOLEAN_INPUT},
    {XrControl::Panel, "panel", "Show or hide the panel", XR_ACTION_TYPE_BOOLEAN_INPUT},
    {XrControl::Scroll, "scroll", "Scroll the panel", XR_ACTION_TYPE_FLOAT_INPUT},
    {XrControl::Haptic, "haptic", "Vibrate", XR_ACTION_TYPE_VIBRATION_OUTPUT},
};

template <std::size_t N>
void copyName(char (&to)[N], const std::string& from) {
  std::strncpy(to, from.c_str(), N - 1);
  to[N - 1] = '\0';
}

bool located(const XrSpaceLocation& location) {
  return (location.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT) &&
         (location.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT);
}

Pose poseOf(const XrPosef& pose) {
  const glm::dquat q(pose.orientation.w, pose.orientation.x, pose.orientation.y,
                     pose.orientation.z);
  // Floats from the runtime: normalised in double so recordings hold exactly unit quaternions.
  return {{pose.position.x, pose.position.y, pose.position.z}, glm::normalize(q)};
}

}  // namespace

HandSide sheetHandSide(HandSide handedness) {
  return otherHand(handedness);
}

HandSide pointHandSide(HandSide handedness) {
  return handedness;
}

XrPath XrInput::path(const std::string& text) const {
  XrPath result = XR_NULL_PATH;
  CHECK_XR(xrStringToPath(instance_, text.c_str(), &result));
  return result;
}

XrInput::XrInput(XrInstance instance, bool handTracking, bool handsOnly,
                 const InteractionThresholds& thresholds)
    : instance_(instance), handsOnly_(handsOnly), hands_(thresholds) {
  if (handTracking) handTracking_ = std::make_unique<XrHandTracking>(instance_);
  handPaths_ = {path(std::string(kXrLeftHand)), path(std::string(kXrRightHand))};

  XrActionSetCreateInfo setInfo{XR_TYPE_ACTION_SET_CREATE_INFO};
  copyName(setInfo.actionSetName, "curvefold");
  copyName(setInfo.localizedActionSetName, "Curved folding");
  CHECK_XR(xrCreateActionSet(instance_, &setInfo, &actionSet_));
  try {
    for (const ActionInfo& info : kActions) {
      XrActionCreateInfo create{XR_TYPE_ACTION_CREATE_INFO};
      create.actionType = info.type;
      copyName(create.actionName, info.name);
      copyName(create.localizedActionName, info.localized);
      create.countSubactionPaths = static_cast<std::uint32_t>(handPaths_.size());
      create.subactionPaths = handPaths_.data();
      XrAction created = XR_NULL_HANDLE;
      CHECK_XR(xrCreateAction(actionSet_, &create, &created));
      actions_[info.control] = created;
    }
    for (const XrProfileControls& profile : xrProfileControls()) {
      std::vector<XrActionSuggestedBinding> bindings;
      for (const XrControlBinding& binding : profile.bindings)
        bindings.push_back(
            {action(binding.control),
             path("/user/hand/" + std::string(binding.hand) + std::string(binding.input))});
      XrInteractionProfileSuggestedBinding suggested{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
      suggested.interactionProfile = path(std::string(profile.profile));
      suggested.countSuggestedBindings = static_cast<std::uint32_t>(bindings.size());
      suggested.suggestedBindings = bindings.data();
      const XrResult result = xrSuggestInteractionProfileBindings(instance_, &suggested);
      // A runtime that lacks a profile refuses it with PATH_UNSUPPORTED; anything else is a bug.
      if (result != XR_ERROR_PATH_UNSUPPORTED)
        xrCheck(result, "xrSuggestInteractionProfileBindings", __FILE__, __LINE__);
      suggestions_.push_back({std::string(profile.profile), result});
    }
  } catch (...) {
    xrDestroyActionSet(actionSet_);
    throw;
  }
}

XrInput::~XrInput() {
  detach();
  if (actionSet_ != XR_NULL_HANDLE) xrDestroyActionSet(actionSet_);  // destroys its actions
}

void XrInput::attach(XrSession session, bool tracksHands) {
  session_ = session;
  tracksHands_ = tracksHands && handTracking_;
  if (tracksHands_) handTracking_->attach(session_);
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &actionSet_;
  CHECK_XR(xrAttachSessionActionSets(session_, &attach));
  for (std::size_t hand = 0; hand < 2; ++hand) {
    XrActionSpaceCreateInfo info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
    info.subactionPath = handPaths_[hand];
    info.poseInActionSpace.orientation.w = 1.0f;
    info.action = action(XrControl::GripPose);
    CHECK_XR(xrCreateActionSpace(session_, &info, &gripSpaces_[hand]));
    info.action = action(XrControl::AimPose);
    CHECK_XR(xrCreateActionSpace(session_, &info, &aimSpaces_[hand]));
  }
}

void XrInput::detach() {
  if (handTracking_) handTracking_->detach();
  tracksHands_ = false;
  for (auto* spaces : {&gripSpaces_, &aimSpaces_})
    for (XrSpace& space : *spaces) {
      if (space != XR_NULL_HANDLE) xrDestroySpace(space);
      space = XR_NULL_HANDLE;
    }
  session_ = XR_NULL_HANDLE;
}

float XrInput::floatState(XrControl control, HandSide hand) const {
  XrActionStateGetInfo info{XR_TYPE_ACTION_STATE_GET_INFO};
  info.action = action(control);
  info.subactionPath = handPaths_[std::size_t(hand)];
  XrActionStateFloat state{XR_TYPE_ACTION_STATE_FLOAT};
  CHECK_XR(xrGetActionStateFloat(session_, &info, &state));
  return state.isActive ? state.currentState : 0.0f;
}

bool XrInput::booleanState(XrControl control, XrPath subaction) const {
  XrActionStateGetInfo info{XR_TYPE_ACTION_STATE_GET_INFO};
  info.action = action(control);
  info.subactionPath = subaction;
  XrActionStateBoolean state{XR_TYPE_ACTION_STATE_BOOLEAN};
  CHECK_XR(xrGetActionStateBoolean(session_, &info, &state));
  return state.isActive && state.currentState;
}

bool XrInput::poll(XrSpace base, XrTime time, HandSide handedness, double seconds,
                   InputFrame& frame) {
  frame = InputFrame{};
  frame.time = seconds;
  pointAim_.reset();
  const XrActiveActionSet active{actionSet_, XR_NULL_PATH};
  XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
  sync.countActiveActionSets = 1;
  sync.activeActionSets = &active;
  if (CHECK_XR(xrSyncActions(session_, &sync)) == XR_SESSION_NOT_FOCUSED) return false;

  const HandSide sheet = sheetHandSide(handedness);
  const HandSide point = pointHandSide(handedness);
  if (handedness != handedness_) {
    // The hands swapped roles: what each role's hand was doing belongs to the other now.
    hands_.resetPointHand();
    hands_.resetSheetHand();
    handedness_ = handedness;
  }
  sheetJoints_ = tracksHands_ ? handTracking_->locate(sheet, base, time) : HandJoints{};
  pointJoints_ = tracksHands_ ? handTracking_->locate(point, base, time) : HandJoints{};
  // Locates a role's controller (its space into `location`) and picks what drives the role: a
  // located controller (unless --hands), else a tracked hand; with neither, whichever drove it last
  // keeps it (a hand out of view holds its pinch). A role that leaves its hand forgets what the
  // hand was doing; a hand that drives its role updates the frame. True when the source changed.
  XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
  auto follow = [&](XrSpace space, const HandJoints& joints, XrHandSource& source,
                    void (HandInput::*resetHand)(),
                    void (HandInput::*updateHand)(const HandJoints&, InputFrame&)) {
    location = XrSpaceLocation{XR_TYPE_SPACE_LOCATION};
    CHECK_XR(xrLocateSpace(space, base, time, &location));
    const XrHandSource now = [&] {
      if (handsOnly_) return XrHandSource::Hand;
      if (located(location)) return XrHandSource::Controller;
      if (joints.tracked) return XrHandSource::Hand;
      return tracksHands_ ? source : XrHandSource::Controller;
    }();
    const bool switched = now != source;
    if (switched && source == XrHandSource::Hand) (hands_.*resetHand)();
    source = now;
    if (source == XrHandSource::Hand) (hands_.*updateHand)(joints, frame);
    return switched;
  };

  const bool sheetSwitched = follow(gripSpaces_[std::size_t(sheet)], sheetJoints_, sheetSource_,
                                    &HandInput::resetSheetHand, &HandInput::updateSheetHand);
  if (sheetSource_ == XrHandSource::Controller) {
    if (located(location)) {
      frame.sheetHand.tracked = true;
      frame.sheetHand.pose = poseOf(location.pose);
    }
    frame.sheetHand.clutch = floatState(XrControl::Clutch, sheet);
  }

  const bool pointSwitched = follow(aimSpaces_[std::size_t(point)], pointJoints_, pointSource_,
                                    &HandInput::resetPointHand, &HandInput::updatePointHand);
  if (pointSource_ == XrHandSource::Controller) {
    if (located(location)) {
      const Pose aim = poseOf(location.pose);
      pointAim_ = aim;
      frame.pointHand.tracked = true;
      frame.pointHand.position = aim.apply({0.0, 0.0, -kXrTipOffset});
      frame.pointHand.aim = aim.orientation;
    }
    frame.pointHand.select = floatState(XrControl::Select, point);
    frame.pointHand.grip = floatState(XrControl::Clutch, point);
    frame.pointHand.scroll = std::clamp(double(floatState(XrControl::Scroll, point)), -1.0, 1.0);
  }
  // A controller's grip or tip and a hand's palm or pinch are not the same place: the frame a
  // role changes source, it reads as lost, so the core re-anchors a held sheet or drag instead of
  // jumping by the difference.
  if (sheetSwitched) frame.sheetHand.tracked = false;
  if (pointSwitched) frame.pointHand.tracked = false;

  auto press = [&](Button button, bool held) {
    if (held) frame.buttons |= static_cast<std::uint32_t>(button);
  };
  press(Button::Cancel, booleanState(XrControl::Cancel, handPaths_[std::size_t(point)]));
  press(Button::Undo, booleanState(XrControl::Undo, handPaths_[std::size_t(sheet)]));
  press(Button::Redo, booleanState(XrControl::Redo, handPaths_[std::size_t(sheet)]));
  press(Button::SwitchHands, booleanState(XrControl::SwitchHands, XR_NULL_PATH));
  press(Button::Panel, booleanState(XrControl::Panel, handPaths_[std::size_t(sheet)]));
  return true;
}

void XrInput::applyHaptics(std::span<const HapticPulse> pulses, HandSide handedness) {
  for (const HapticPulse& pulse : pulses) {
    const HandSide side =
        pulse.hand == HapticHand::Sheet ? sheetHandSide(handedness) : pointHandSide(handedness);
    XrHapticActionInfo info{XR_TYPE_HAPTIC_ACTION_INFO};
    info.action = action(XrControl::Haptic);
    info.subactionPath = handPaths_[std::size_t(side)];
    XrHapticVibration vibration{XR_TYPE_HAPTIC_VIBRATION};
    vibration.amplitude = static_cast<float>(pulse.amplitude);
    vibration.duration = static_cast<XrDuration>(pulse.duration * 1e9);
    vibration.frequency = XR_FREQUENCY_UNSPECIFIED;
    CHECK_XR(xrApplyHapticFeedback(session_, &info,
                                   reinterpret_cast<const XrHapticBaseHeader*>(&vibration)));
  }
}

std::array<std::string, 2> XrInput::currentProfiles() const {
  std::array<std::string, 2> result;
  for (std::size_t hand = 0; hand < 2; ++hand) {
    XrInteractionProfileState state{XR_TYPE_INTERACTION_PROFILE_STATE};
    CHECK_XR(xrGetCurrentInteractionProfile(session_, handPaths_[hand], &state));
    if (state.interactionProfile == XR_NULL_PATH) continue;
    char text[XR_MAX_PATH_LENGTH];
    std::uint32_t length = 0;
    CHECK_XR(xrPathToString(instance_, state.interactionProfile, sizeof text, &length, text));
    result[hand] = text;
  }
  return result;
}

}  // namespace curvefold
