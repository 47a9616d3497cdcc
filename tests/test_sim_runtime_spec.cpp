// The simulated runtime held to the OpenXR specification on its own, through the real Khronos
// loader and raw OpenXR calls, without curvefold's XR program: the session's state machine, frame
// call order, the frame's time, and suggested-binding paths. A misreading of the specification
// shared by the program and the runtime would pass test_xr; it cannot pass these, which state the
// specification's rules directly (OpenXR 1.0, chapters "Session", "Rendering" and "Input").
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <openxr/openxr.h>

namespace {

// A headless instance and session (XR_MND_headless: no graphics binding needed) on the simulated
// runtime, holding its last frame so it never asks to exit on its own.
class SimRuntimeSpec : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("XR_RUNTIME_JSON", CURVEFOLD_SIM_RUNTIME_JSON, 1);
    setenv("CURVEFOLD_SIM_HOLD", "1", 1);
    unsetenv("CURVEFOLD_SIM_INPUT");
    const char* extensions[] = {"XR_MND_headless"};
    XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
    std::snprintf(info.applicationInfo.applicationName, XR_MAX_APPLICATION_NAME_SIZE, "spec");
    info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    info.enabledExtensionCount = 1;
    info.enabledExtensionNames = extensions;
    ASSERT_EQ(xrCreateInstance(&info, &instance_), XR_SUCCESS);
    XrSystemGetInfo system{XR_TYPE_SYSTEM_GET_INFO};
    system.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    ASSERT_EQ(xrGetSystem(instance_, &system, &system_), XR_SUCCESS);
  }
  void TearDown() override {
    if (session_ != XR_NULL_HANDLE) xrDestroySession(session_);
    if (instance_ != XR_NULL_HANDLE) xrDestroyInstance(instance_);
    unsetenv("CURVEFOLD_SIM_HOLD");
  }

  void createSession() {
    XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
    info.systemId = system_;
    ASSERT_EQ(xrCreateSession(instance_, &info, &session_), XR_SUCCESS);
  }
  // Session states reported since the last call, in order.
  std::vector<XrSessionState> states() {
    std::vector<XrSessionState> seen;
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
    while (xrPollEvent(instance_, &event) == XR_SUCCESS) {
      if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED)
        seen.push_back(reinterpret_cast<XrEventDataSessionStateChanged&>(event).state);
      event = {XR_TYPE_EVENT_DATA_BUFFER};
    }
    return seen;
  }
  XrResult begin() {
    XrSessionBeginInfo info{XR_TYPE_SESSION_BEGIN_INFO};
    info.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    return xrBeginSession(session_, &info);
  }
  XrResult wait(XrFrameState& state) {
    state = {XR_TYPE_FRAME_STATE};
    return xrWaitFrame(session_, nullptr, &state);
  }
  XrResult beginFrame() { return xrBeginFrame(session_, nullptr); }
  XrResult endFrame(XrTime displayTime) {
    XrFrameEndInfo info{XR_TYPE_FRAME_END_INFO};
    info.displayTime = displayTime;
    info.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    return xrEndFrame(session_, &info);
  }

  XrInstance instance_ = XR_NULL_HANDLE;
  XrSystemId system_ = XR_NULL_SYSTEM_ID;
  XrSession session_ = XR_NULL_HANDLE;
};

// "Session Lifecycle": a new session is IDLE, then READY; xrBeginSession is allowed only in READY
// and only once; frames make it SYNCHRONIZED, VISIBLE, FOCUSED; xrRequestExitSession leads to
// STOPPING, where alone xrEndSession is allowed, and then IDLE and EXITING.
TEST_F(SimRuntimeSpec, TheSessionStateMachineFollowsTheSpecification) {
  createSession();
  EXPECT_EQ(states(), (std::vector<XrSessionState>{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_READY}));
  EXPECT_EQ(xrEndSession(session_), XR_ERROR_SESSION_NOT_RUNNING);
  XrSessionBeginInfo wrong{XR_TYPE_SESSION_BEGIN_INFO};
  wrong.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO;
  EXPECT_EQ(xrBeginSession(session_, &wrong), XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED);
  ASSERT_EQ(begin(), XR_SUCCESS);
  EXPECT_EQ(begin(), XR_ERROR_SESSION_RUNNING);
  EXPECT_EQ(states(), (std::vector<XrSessionState>{XR_SESSION_STATE_SYNCHRONIZED}));
  EXPECT_EQ(xrEndSession(session_), XR_ERROR_SESSION_NOT_STOPPING);  // not asked to stop yet
  XrFrameState frame;
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(wait(frame), XR_SUCCESS);
    ASSERT_EQ(beginFrame(), XR_SUCCESS);
    ASSERT_EQ(endFrame(frame.predictedDisplayTime), XR_SUCCESS);
  }
  EXPECT_EQ(states(),
            (std::vector<XrSessionState>{XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_FOCUSED}));
  ASSERT_EQ(xrRequestExitSession(session_), XR_SUCCESS);
  const std::vector<XrSessionState> stopping = states();
  ASSERT_FALSE(stopping.empty());
  EXPECT_EQ(stopping.back(), XR_SESSION_STATE_STOPPING);
  ASSERT_EQ(xrEndSession(session_), XR_SUCCESS);
  EXPECT_EQ(states(),
            (std::vector<XrSessionState>{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING}));
  EXPECT_EQ(xrEndSession(session_), XR_ERROR_SESSION_NOT_RUNNING);
}

// "Frame Synchronization": xrWaitFrame needs a running session; xrBeginFrame needs a preceding
// xrWaitFrame; xrEndFrame needs a preceding xrBeginFrame; a second xrBeginFrame without an
// xrEndFrame discards the first frame (XR_FRAME_DISCARDED, a success); xrEndFrame refuses a
// display time that no xrWaitFrame could have predicted.
TEST_F(SimRuntimeSpec, FrameCallsComeInTheSpecifiedOrder) {
  createSession();
  XrFrameState frame;
  EXPECT_EQ(wait(frame), XR_ERROR_SESSION_NOT_RUNNING);
  EXPECT_EQ(beginFrame(), XR_ERROR_SESSION_NOT_RUNNING);
  states();
  ASSERT_EQ(begin(), XR_SUCCESS);
  EXPECT_EQ(beginFrame(), XR_ERROR_CALL_ORDER_INVALID);  // no xrWaitFrame yet
  EXPECT_EQ(endFrame(1), XR_ERROR_CALL_ORDER_INVALID);   // no xrBeginFrame yet
  ASSERT_EQ(wait(frame), XR_SUCCESS);
  EXPECT_GT(frame.predictedDisplayTime, 0);
  EXPECT_GT(frame.predictedDisplayPeriod, 0);
  ASSERT_EQ(beginFrame(), XR_SUCCESS);
  EXPECT_EQ(beginFrame(), XR_ERROR_CALL_ORDER_INVALID);  // one xrBeginFrame per xrWaitFrame
  ASSERT_EQ(wait(frame), XR_SUCCESS);
  EXPECT_EQ(beginFrame(), XR_FRAME_DISCARDED);  // the frame begun before was never ended
  EXPECT_EQ(endFrame(0), XR_ERROR_TIME_INVALID);
  EXPECT_EQ(endFrame(frame.predictedDisplayTime), XR_SUCCESS);
  EXPECT_EQ(endFrame(frame.predictedDisplayTime), XR_ERROR_CALL_ORDER_INVALID);  // ended already
}

// "Suggested Bindings": a path a profile does not define is refused with
// XR_ERROR_PATH_UNSUPPORTED, and so is a profile the runtime does not know; a path it defines is
// accepted; after xrAttachSessionActionSets no binding can be suggested.
TEST_F(SimRuntimeSpec, SuggestedBindingsAreCheckedAgainstTheProfile) {
  XrActionSet set = XR_NULL_HANDLE;
  XrActionSetCreateInfo setInfo{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::snprintf(setInfo.actionSetName, XR_MAX_ACTION_SET_NAME_SIZE, "spec");
  std::snprintf(setInfo.localizedActionSetName, XR_MAX_LOCALIZED_ACTION_SET_NAME_SIZE, "Spec");
  ASSERT_EQ(xrCreateActionSet(instance_, &setInfo, &set), XR_SUCCESS);
  XrAction action = XR_NULL_HANDLE;
  XrActionCreateInfo actionInfo{XR_TYPE_ACTION_CREATE_INFO};
  actionInfo.actionType = XR_ACTION_TYPE_FLOAT_INPUT;
  std::snprintf(actionInfo.actionName, XR_MAX_ACTION_NAME_SIZE, "squeeze");
  std::snprintf(actionInfo.localizedActionName, XR_MAX_LOCALIZED_ACTION_NAME_SIZE, "Squeeze");
  ASSERT_EQ(xrCreateAction(set, &actionInfo, &action), XR_SUCCESS);
  auto suggest = [&](const char* profile, const char* binding) {
    XrPath profilePath = XR_NULL_PATH, bindingPath = XR_NULL_PATH;
    xrStringToPath(instance_, profile, &profilePath);
    xrStringToPath(instance_, binding, &bindingPath);
    const XrActionSuggestedBinding suggested{action, bindingPath};
    XrInteractionProfileSuggestedBinding info{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
    info.interactionProfile = profilePath;
    info.countSuggestedBindings = 1;
    info.suggestedBindings = &suggested;
    return xrSuggestInteractionProfileBindings(instance_, &info);
  };
  const char* touch = "/interaction_profiles/oculus/touch_controller";
  EXPECT_EQ(suggest(touch, "/user/hand/left/input/squeeze/value"), XR_SUCCESS);
  // The Touch controller has no trackpad; the Vive has no squeeze value (only a click).
  EXPECT_EQ(suggest(touch, "/user/hand/left/input/trackpad/x"), XR_ERROR_PATH_UNSUPPORTED);
  EXPECT_EQ(
      suggest("/interaction_profiles/htc/vive_controller", "/user/hand/right/input/squeeze/value"),
      XR_ERROR_PATH_UNSUPPORTED);
  EXPECT_EQ(suggest("/interaction_profiles/acme/tricorder", "/user/hand/left/input/x/click"),
            XR_ERROR_PATH_UNSUPPORTED);
  createSession();
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &set;
  ASSERT_EQ(xrAttachSessionActionSets(session_, &attach), XR_SUCCESS);
  EXPECT_EQ(suggest(touch, "/user/hand/right/input/squeeze/value"),
            XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
  EXPECT_EQ(xrAttachSessionActionSets(session_, &attach), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
}

}  // namespace
