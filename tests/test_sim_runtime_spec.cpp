// The simulated runtime held to the OpenXR specification on its own, through the real Khronos
// loader and raw OpenXR calls, without curvefold's XR program: the session's state machine, frame
// call order, the frame's time, and suggested-binding paths. A misreading of the specification
// shared by the program and the runtime would pass test_xr; it cannot pass these, which state the
// specification's rules directly (OpenXR 1.0, chapters "Session", "Rendering" and "Input", and
// the XR_EXT_hand_tracking extension).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <dlfcn.h>

#include <gtest/gtest.h>
#include <vulkan/vulkan.h>

#include "app/xr/xr_vulkan_graphics.hpp"
#include "sim_input/xr_runtime/loader_negotiation.hpp"
#include "test_paths.hpp"

namespace {

// A headless instance and session (XR_MND_headless: no graphics binding needed) on the simulated
// runtime, holding its last frame so it never asks to exit on its own.
class SimRuntimeSpec : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("XR_RUNTIME_JSON", CURVEFOLD_SIM_RUNTIME_JSON, 1);
    setenv("CURVEFOLD_SIM_HOLD", "1", 1);
    unsetenv("CURVEFOLD_SIM_INPUT");
    prepare();
    const std::vector<const char*> extensions = this->extensions();
    XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
    std::snprintf(info.applicationInfo.applicationName, XR_MAX_APPLICATION_NAME_SIZE, "spec");
    info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    info.enabledExtensionCount = std::uint32_t(extensions.size());
    info.enabledExtensionNames = extensions.data();
    ASSERT_EQ(xrCreateInstance(&info, &instance_), XR_SUCCESS);
    XrSystemGetInfo system{XR_TYPE_SYSTEM_GET_INFO};
    system.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    ASSERT_EQ(xrGetSystem(instance_, &system, &system_), XR_SUCCESS);
  }
  void TearDown() override {
    if (session_ != XR_NULL_HANDLE) xrDestroySession(session_);
    if (instance_ != XR_NULL_HANDLE) xrDestroyInstance(instance_);
    unsetenv("CURVEFOLD_SIM_HOLD");
    unsetenv("CURVEFOLD_SIM_HANDS");
    unsetenv("CURVEFOLD_SIM_INPUT");
  }
  // Before the instance: the environment and extensions a fixture needs.
  virtual void prepare() {}
  virtual std::vector<const char*> extensions() const { return {"XR_MND_headless"}; }

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

// "Swapchain Image Management" with XR_KHR_vulkan_enable2: the runtime offers its formats in
// order of preference, sRGB first (the specification asks runtimes to prefer sRGB), each colour
// format also as UNORM, and depth formats; it refuses a format it did not offer, an empty array,
// and acquiring more images than it has; images come out in acquire order and are released in it;
// and a layer that names an array layer the swapchain does not have is a validation failure. The
// app's Vulkan plugin only makes the device here (through the runtime, as the extension says).
TEST(SimRuntimeSwapchains, FormatsArraysAndImageOrderFollowTheSpecification) {
  setenv("XR_RUNTIME_JSON", CURVEFOLD_SIM_RUNTIME_JSON, 1);
  setenv("CURVEFOLD_SIM_HOLD", "1", 1);
  unsetenv("CURVEFOLD_SIM_INPUT");
  curvefold::xr::XrVulkanGraphics graphics(/*validation=*/false);
  const std::vector<std::string> wanted = graphics.instanceExtensions();
  std::vector<const char*> extensions;
  for (const std::string& e : wanted) extensions.push_back(e.c_str());
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::snprintf(info.applicationInfo.applicationName, XR_MAX_APPLICATION_NAME_SIZE, "spec");
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = std::uint32_t(extensions.size());
  info.enabledExtensionNames = extensions.data();
  XrInstance instance = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateInstance(&info, &instance), XR_SUCCESS);
  XrSystemGetInfo systemInfo{XR_TYPE_SYSTEM_GET_INFO};
  systemInfo.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  ASSERT_EQ(xrGetSystem(instance, &systemInfo, &system), XR_SUCCESS);
  graphics.initializeDevice(instance, system);
  XrSessionCreateInfo sessionInfo{XR_TYPE_SESSION_CREATE_INFO};
  sessionInfo.next = graphics.sessionBinding();
  sessionInfo.systemId = system;
  XrSession session = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateSession(instance, &sessionInfo, &session), XR_SUCCESS);

  std::uint32_t count = 0;
  ASSERT_EQ(xrEnumerateSwapchainFormats(session, 0, &count, nullptr), XR_SUCCESS);
  std::vector<std::int64_t> formats(count);
  std::uint32_t tooFew = 0;
  EXPECT_EQ(xrEnumerateSwapchainFormats(session, 1, &tooFew, formats.data()),
            XR_ERROR_SIZE_INSUFFICIENT);
  ASSERT_EQ(xrEnumerateSwapchainFormats(session, count, &count, formats.data()), XR_SUCCESS);
  ASSERT_GE(formats.size(), 4u);
  EXPECT_EQ(formats[0], VK_FORMAT_R8G8B8A8_SRGB);  // preferred first
  auto offered = [&](VkFormat f) {
    return std::find(formats.begin(), formats.end(), std::int64_t(f)) != formats.end();
  };
  EXPECT_TRUE(offered(VK_FORMAT_R8G8B8A8_UNORM));
  EXPECT_TRUE(offered(VK_FORMAT_B8G8R8A8_SRGB));
  EXPECT_TRUE(offered(VK_FORMAT_D32_SFLOAT) || offered(VK_FORMAT_D24_UNORM_S8_UINT) ||
              offered(VK_FORMAT_D16_UNORM));

  XrSwapchainCreateInfo create{XR_TYPE_SWAPCHAIN_CREATE_INFO};
  create.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT;
  create.format = VK_FORMAT_R8G8B8A8_SRGB;
  create.sampleCount = 1;
  create.width = 64;
  create.height = 48;
  create.faceCount = 1;
  create.mipCount = 1;
  create.arraySize = 2;
  XrSwapchain swapchain = XR_NULL_HANDLE, refused = XR_NULL_HANDLE;
  XrSwapchainCreateInfo bad = create;
  bad.format = VK_FORMAT_R16G16B16A16_SFLOAT;  // not offered
  EXPECT_EQ(xrCreateSwapchain(session, &bad, &refused), XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED);
  bad = create;
  bad.arraySize = 0;
  EXPECT_EQ(xrCreateSwapchain(session, &bad, &refused), XR_ERROR_VALIDATION_FAILURE);
  ASSERT_EQ(xrCreateSwapchain(session, &create, &swapchain), XR_SUCCESS);
  std::uint32_t images = 0;
  ASSERT_EQ(xrEnumerateSwapchainImages(swapchain, 0, &images, nullptr), XR_SUCCESS);
  ASSERT_GE(images, 2u);

  // Running, one frame, every image acquired in turn: the next acquire has none left.
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
  while (xrPollEvent(instance, &event) == XR_SUCCESS) event = {XR_TYPE_EVENT_DATA_BUFFER};
  XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
  begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  ASSERT_EQ(xrBeginSession(session, &begin), XR_SUCCESS);
  XrFrameState frame{XR_TYPE_FRAME_STATE};
  ASSERT_EQ(xrWaitFrame(session, nullptr, &frame), XR_SUCCESS);
  ASSERT_EQ(xrBeginFrame(session, nullptr), XR_SUCCESS);
  XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
  XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
  wait.timeout = XR_INFINITE_DURATION;
  XrSwapchainImageReleaseInfo release{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
  EXPECT_EQ(xrReleaseSwapchainImage(swapchain, &release), XR_ERROR_CALL_ORDER_INVALID);
  std::vector<std::uint32_t> order;
  for (std::uint32_t i = 0; i < images; ++i) {
    std::uint32_t index = 0;
    ASSERT_EQ(xrAcquireSwapchainImage(swapchain, &acquire, &index), XR_SUCCESS);
    order.push_back(index);
  }
  std::uint32_t extra = 0;
  EXPECT_EQ(xrAcquireSwapchainImage(swapchain, &acquire, &extra), XR_ERROR_CALL_ORDER_INVALID);
  for (std::uint32_t i = 0; i < images; ++i) {
    ASSERT_EQ(xrWaitSwapchainImage(swapchain, &wait), XR_SUCCESS);
    ASSERT_EQ(xrReleaseSwapchainImage(swapchain, &release), XR_SUCCESS);
  }
  for (std::uint32_t i = 0; i < images; ++i) EXPECT_EQ(order[i], i);  // round robin from 0

  // A projection layer naming layer 2 of a 2-layer swapchain.
  XrReferenceSpaceCreateInfo spaceInfo{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  spaceInfo.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  spaceInfo.poseInReferenceSpace.orientation.w = 1.0f;
  XrSpace space = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateReferenceSpace(session, &spaceInfo, &space), XR_SUCCESS);
  XrCompositionLayerProjectionView views[2] = {{XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW},
                                               {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW}};
  for (std::uint32_t v = 0; v < 2; ++v) {
    views[v].pose.orientation.w = 1.0f;
    views[v].fov = {-0.8f, 0.8f, 0.8f, -0.8f};
    views[v].subImage.swapchain = swapchain;
    views[v].subImage.imageRect = {{0, 0}, {64, 48}};
    views[v].subImage.imageArrayIndex = v == 0 ? 0 : 2;
  }
  XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  layer.space = space;
  layer.viewCount = 2;
  layer.views = views;
  const XrCompositionLayerBaseHeader* layers[] = {
      reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = frame.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  end.layerCount = 1;
  end.layers = layers;
  EXPECT_EQ(xrEndFrame(session, &end), XR_ERROR_VALIDATION_FAILURE);
  views[1].subImage.imageArrayIndex = 1;
  EXPECT_EQ(xrEndFrame(session, &end), XR_SUCCESS);

  xrDestroySpace(space);
  xrDestroySwapchain(swapchain);
  graphics.swapchainsDestroyed();
  xrDestroySession(session);
  xrDestroyInstance(instance);
  unsetenv("CURVEFOLD_SIM_HOLD");
}

}  // namespace

namespace {

// XR_EXT_hand_tracking, enabled, with hands served from a recording (CURVEFOLD_SIM_HANDS=1).
class SimRuntimeHands : public SimRuntimeSpec {
 protected:
  void prepare() override {
    setenv("CURVEFOLD_SIM_HANDS", "1", 1);
    setenv("CURVEFOLD_SIM_INPUT",
           (std::string(CURVEFOLD_SOURCE_DIR) + "/examples/recordings/cone.jsonl").c_str(), 1);
  }
  std::vector<const char*> extensions() const override {
    return {"XR_MND_headless", XR_EXT_HAND_TRACKING_EXTENSION_NAME};
  }
  template <typename Function>
  Function function(const char* name) {
    PFN_xrVoidFunction found = nullptr;
    EXPECT_EQ(xrGetInstanceProcAddr(instance_, name, &found), XR_SUCCESS) << name;
    return reinterpret_cast<Function>(found);
  }
};

// Chapter "XR_EXT_hand_tracking": the system says it tracks hands; a tracker needs a valid hand
// and joint set; xrLocateHandJointsEXT needs the joint set's count and a valid time, and returns
// either an active hand with every joint's position and orientation valid or an inactive one
// with none (here: until the session is focused); velocities may be chained; the trackers die
// with their session.
TEST_F(SimRuntimeHands, HandTrackingFollowsTheExtension) {
  XrSystemHandTrackingPropertiesEXT hands{XR_TYPE_SYSTEM_HAND_TRACKING_PROPERTIES_EXT};
  XrSystemProperties properties{XR_TYPE_SYSTEM_PROPERTIES};
  properties.next = &hands;
  ASSERT_EQ(xrGetSystemProperties(instance_, system_, &properties), XR_SUCCESS);
  EXPECT_EQ(hands.supportsHandTracking, XR_TRUE);

  auto create = function<PFN_xrCreateHandTrackerEXT>("xrCreateHandTrackerEXT");
  auto destroy = function<PFN_xrDestroyHandTrackerEXT>("xrDestroyHandTrackerEXT");
  auto locate = function<PFN_xrLocateHandJointsEXT>("xrLocateHandJointsEXT");
  ASSERT_TRUE(create && destroy && locate);
  createSession();
  XrHandTrackerCreateInfoEXT info{XR_TYPE_HAND_TRACKER_CREATE_INFO_EXT};
  info.handJointSet = XR_HAND_JOINT_SET_DEFAULT_EXT;
  XrHandTrackerEXT left = XR_NULL_HANDLE, right = XR_NULL_HANDLE, spare = XR_NULL_HANDLE;
  info.hand = static_cast<XrHandEXT>(3);
  EXPECT_EQ(create(session_, &info, &spare), XR_ERROR_VALIDATION_FAILURE);
  info.hand = XR_HAND_LEFT_EXT;
  info.handJointSet = static_cast<XrHandJointSetEXT>(7);
  EXPECT_EQ(create(session_, &info, &spare), XR_ERROR_VALIDATION_FAILURE);
  info.handJointSet = XR_HAND_JOINT_SET_DEFAULT_EXT;
  ASSERT_EQ(create(session_, &info, &left), XR_SUCCESS);
  info.hand = XR_HAND_RIGHT_EXT;
  ASSERT_EQ(create(session_, &info, &right), XR_SUCCESS);

  XrSpace local = XR_NULL_HANDLE;
  XrReferenceSpaceCreateInfo spaceInfo{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  spaceInfo.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  spaceInfo.poseInReferenceSpace.orientation.w = 1.0f;
  ASSERT_EQ(xrCreateReferenceSpace(session_, &spaceInfo, &local), XR_SUCCESS);
  XrHandJointLocationEXT joints[XR_HAND_JOINT_COUNT_EXT];
  XrHandJointVelocityEXT speeds[XR_HAND_JOINT_COUNT_EXT];
  XrHandJointVelocitiesEXT velocities{XR_TYPE_HAND_JOINT_VELOCITIES_EXT};
  velocities.jointCount = XR_HAND_JOINT_COUNT_EXT;
  velocities.jointVelocities = speeds;
  XrHandJointLocationsEXT locations{XR_TYPE_HAND_JOINT_LOCATIONS_EXT};
  locations.jointCount = XR_HAND_JOINT_COUNT_EXT;
  locations.jointLocations = joints;
  XrHandJointsLocateInfoEXT where{XR_TYPE_HAND_JOINTS_LOCATE_INFO_EXT};
  where.baseSpace = local;
  where.time = 1;
  auto countValid = [&] {
    int valid = 0;
    for (const XrHandJointLocationEXT& joint : joints)
      valid += (joint.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT) &&
               (joint.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT);
    return valid;
  };
  // Not focused yet: inactive, nothing valid.
  ASSERT_EQ(locate(right, &where, &locations), XR_SUCCESS);
  EXPECT_EQ(locations.isActive, XR_FALSE);
  EXPECT_EQ(countValid(), 0);

  ASSERT_EQ(begin(), XR_SUCCESS);
  XrFrameState frame;
  for (int i = 0; i < 4; ++i) {  // to FOCUSED, then a frame served while focused
    ASSERT_EQ(wait(frame), XR_SUCCESS);
    ASSERT_EQ(beginFrame(), XR_SUCCESS);
    ASSERT_EQ(endFrame(frame.predictedDisplayTime), XR_SUCCESS);
  }
  where.time = frame.predictedDisplayTime;
  locations.jointCount = XR_HAND_JOINT_COUNT_EXT - 1;
  EXPECT_EQ(locate(right, &where, &locations), XR_ERROR_VALIDATION_FAILURE);
  locations.jointCount = XR_HAND_JOINT_COUNT_EXT;
  where.time = 0;
  EXPECT_EQ(locate(right, &where, &locations), XR_ERROR_TIME_INVALID);
  where.time = frame.predictedDisplayTime;
  locations.next = &velocities;
  ASSERT_EQ(locate(right, &where, &locations), XR_SUCCESS);
  EXPECT_EQ(locations.isActive, XR_TRUE);
  EXPECT_EQ(countValid(), XR_HAND_JOINT_COUNT_EXT);
  EXPECT_EQ(speeds[XR_HAND_JOINT_PALM_EXT].velocityFlags, 0u);
  // A hand's size: wrist to middle fingertip.
  const XrVector3f a = joints[XR_HAND_JOINT_WRIST_EXT].pose.position;
  const XrVector3f b = joints[XR_HAND_JOINT_MIDDLE_TIP_EXT].pose.position;
  const float length =
      std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
  EXPECT_GT(length, 0.12f);
  EXPECT_LT(length, 0.25f);
  // The left hand holds the sheet; both are served.
  ASSERT_EQ(locate(left, &where, &locations), XR_SUCCESS);
  EXPECT_EQ(locations.isActive, XR_TRUE);
  EXPECT_EQ(destroy(left), XR_SUCCESS);
  EXPECT_EQ(locate(left, &where, &locations), XR_ERROR_HANDLE_INVALID);
  // The session's trackers go with it.
  xrDestroySpace(local);
  ASSERT_EQ(xrDestroySession(session_), XR_SUCCESS);
  session_ = XR_NULL_HANDLE;
  EXPECT_EQ(locate(right, &where, &locations), XR_ERROR_HANDLE_INVALID);
}

// An extension's functions exist only for an instance that enabled it.
TEST_F(SimRuntimeSpec, HandTrackingFunctionsNeedTheExtension) {
  PFN_xrVoidFunction found = nullptr;
  EXPECT_EQ(xrGetInstanceProcAddr(instance_, "xrLocateHandJointsEXT", &found),
            XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(found, nullptr);
}

// "xrResultToString" and "xrStructureTypeToString": an enumerant's own name; a value the runtime
// does not know is named XR_UNKNOWN_SUCCESS_, XR_UNKNOWN_FAILURE_ (by its sign) or
// XR_UNKNOWN_STRUCTURE_TYPE_ with its number, and fits the buffer.
TEST_F(SimRuntimeSpec, ResultsAndStructureTypesAreNamedAsTheSpecificationNamesThem) {
  char result[XR_MAX_RESULT_STRING_SIZE];
  ASSERT_EQ(xrResultToString(instance_, XR_ERROR_HANDLE_INVALID, result), XR_SUCCESS);
  EXPECT_STREQ(result, "XR_ERROR_HANDLE_INVALID");
  ASSERT_EQ(xrResultToString(instance_, XR_SESSION_LOSS_PENDING, result), XR_SUCCESS);
  EXPECT_STREQ(result, "XR_SESSION_LOSS_PENDING");
  ASSERT_EQ(xrResultToString(instance_, XrResult(-987654), result), XR_SUCCESS);
  EXPECT_STREQ(result, "XR_UNKNOWN_FAILURE_-987654");
  ASSERT_EQ(xrResultToString(instance_, XrResult(987654), result), XR_SUCCESS);
  EXPECT_STREQ(result, "XR_UNKNOWN_SUCCESS_987654");
  char type[XR_MAX_STRUCTURE_NAME_SIZE];
  ASSERT_EQ(xrStructureTypeToString(instance_, XR_TYPE_INSTANCE_CREATE_INFO, type), XR_SUCCESS);
  EXPECT_STREQ(type, "XR_TYPE_INSTANCE_CREATE_INFO");
  ASSERT_EQ(xrStructureTypeToString(instance_, XR_TYPE_HAND_JOINT_LOCATIONS_EXT, type), XR_SUCCESS);
  EXPECT_STREQ(type, "XR_TYPE_HAND_JOINT_LOCATIONS_EXT");
  ASSERT_EQ(xrStructureTypeToString(instance_, XrStructureType(987654), type), XR_SUCCESS);
  EXPECT_STREQ(type, "XR_UNKNOWN_STRUCTURE_TYPE_987654");
}

// The runtime's own xrGetInstanceProcAddr, as the loader gets it from the negotiation: the loader
// answers some names itself, so its rules are checked here without it.
class SimRuntimeDispatch : public ::testing::Test {
 protected:
  void SetUp() override {
    unsetenv("CURVEFOLD_SIM_INPUT");
    unsetenv("CURVEFOLD_SIM_NO_HAND_TRACKING");
    library_ = dlopen(CURVEFOLD_SIM_RUNTIME_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(library_, nullptr) << dlerror();
    using namespace curvefold::simxr;
    using Negotiate = XrResult (*)(const XrNegotiateLoaderInfo*, XrNegotiateRuntimeRequest*);
    const auto negotiate =
        reinterpret_cast<Negotiate>(dlsym(library_, "xrNegotiateLoaderRuntimeInterface"));
    ASSERT_NE(negotiate, nullptr);
    XrNegotiateLoaderInfo loader{XR_LOADER_INTERFACE_STRUCT_LOADER_INFO,
                                 kLoaderInfoStructVersion,
                                 sizeof(XrNegotiateLoaderInfo),
                                 kLoaderRuntimeInterfaceVersion,
                                 kLoaderRuntimeInterfaceVersion,
                                 XR_MAKE_VERSION(1, 0, 0),
                                 XR_CURRENT_API_VERSION};
    XrNegotiateRuntimeRequest request{XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST,
                                      kRuntimeInfoStructVersion, sizeof(XrNegotiateRuntimeRequest)};
    ASSERT_EQ(negotiate(&loader, &request), XR_SUCCESS);
    getProcAddr_ = request.getInstanceProcAddr;
    ASSERT_NE(getProcAddr_, nullptr);
  }
  void TearDown() override {
    if (library_) dlclose(library_);
  }
  // The result of looking `name` up, and whether a function came with it exactly on success.
  XrResult lookUp(XrInstance instance, const char* name) {
    // Not null: the runtime must clear it when it finds nothing.
    PFN_xrVoidFunction found = reinterpret_cast<PFN_xrVoidFunction>(&dlclose);
    const XrResult result = getProcAddr_(instance, name, &found);
    EXPECT_EQ(found != nullptr, result == XR_SUCCESS) << name;
    return result;
  }
  XrInstance createInstance(std::vector<const char*> extensions) {
    PFN_xrVoidFunction create = nullptr;
    EXPECT_EQ(getProcAddr_(XR_NULL_HANDLE, "xrCreateInstance", &create), XR_SUCCESS);
    XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
    info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    info.enabledExtensionCount = std::uint32_t(extensions.size());
    info.enabledExtensionNames = extensions.data();
    XrInstance instance = XR_NULL_HANDLE;
    EXPECT_EQ(reinterpret_cast<PFN_xrCreateInstance>(create)(&info, &instance), XR_SUCCESS);
    return instance;
  }
  void destroyInstance(XrInstance instance) {
    PFN_xrVoidFunction destroy = nullptr;
    ASSERT_EQ(getProcAddr_(instance, "xrDestroyInstance", &destroy), XR_SUCCESS);
    EXPECT_EQ(reinterpret_cast<PFN_xrDestroyInstance>(destroy)(instance), XR_SUCCESS);
  }

  void* library_ = nullptr;
  PFN_xrGetInstanceProcAddr getProcAddr_ = nullptr;
};

// "xrGetInstanceProcAddr": with XR_NULL_HANDLE only the functions that make an instance may be
// fetched; any other function the runtime has is XR_ERROR_HANDLE_INVALID; a name it does not have
// is XR_ERROR_FUNCTION_UNSUPPORTED.
TEST_F(SimRuntimeDispatch, WithoutAnInstanceOnlyTheFunctionsThatMakeOneResolve) {
  for (const char* name :
       {"xrGetInstanceProcAddr", "xrEnumerateInstanceExtensionProperties", "xrCreateInstance"})
    EXPECT_EQ(lookUp(XR_NULL_HANDLE, name), XR_SUCCESS) << name;
  for (const char* name : {"xrDestroyInstance", "xrGetSystem", "xrCreateSession", "xrEndFrame",
                           "xrGetVulkanGraphicsDevice2KHR", "xrCreateHandTrackerEXT"})
    EXPECT_EQ(lookUp(XR_NULL_HANDLE, name), XR_ERROR_HANDLE_INVALID) << name;
  EXPECT_EQ(lookUp(XR_NULL_HANDLE, "xrNoSuchFunction"), XR_ERROR_FUNCTION_UNSUPPORTED);
  PFN_xrVoidFunction found = nullptr;
  EXPECT_EQ(getProcAddr_(XR_NULL_HANDLE, nullptr, &found), XR_ERROR_VALIDATION_FAILURE);
  EXPECT_EQ(getProcAddr_(XR_NULL_HANDLE, "xrCreateInstance", nullptr), XR_ERROR_VALIDATION_FAILURE);
}

// With an instance, every core function resolves; XR_EXT_hand_tracking's and
// XR_KHR_vulkan_enable2's only when the instance enabled them (XR_ERROR_FUNCTION_UNSUPPORTED
// otherwise), and an unknown name never.
TEST_F(SimRuntimeDispatch, ExtensionFunctionsResolveOnlyWhenTheExtensionIsEnabled) {
  const char* const core[] = {
      "xrGetInstanceProcAddr", "xrCreateInstance", "xrDestroyInstance",
      "xrGetSystem",           "xrPollEvent",      "xrCreateSession",
      "xrWaitFrame",           "xrSyncActions",    "xrReleaseSwapchainImage"};
  const char* const hands[] = {"xrCreateHandTrackerEXT", "xrDestroyHandTrackerEXT",
                               "xrLocateHandJointsEXT"};
  const char* const vulkan[] = {"xrGetVulkanGraphicsRequirements2KHR", "xrCreateVulkanInstanceKHR",
                                "xrGetVulkanGraphicsDevice2KHR", "xrCreateVulkanDeviceKHR"};
  XrInstance instance = createInstance({"XR_MND_headless"});
  ASSERT_NE(instance, XR_NULL_HANDLE);
  for (const char* name : core) EXPECT_EQ(lookUp(instance, name), XR_SUCCESS) << name;
  for (const char* name : hands)
    EXPECT_EQ(lookUp(instance, name), XR_ERROR_FUNCTION_UNSUPPORTED) << name;
  for (const char* name : vulkan)
    EXPECT_EQ(lookUp(instance, name), XR_ERROR_FUNCTION_UNSUPPORTED) << name;
  EXPECT_EQ(lookUp(instance, "xrNoSuchFunction"), XR_ERROR_FUNCTION_UNSUPPORTED);
  destroyInstance(instance);

  instance = createInstance({"XR_MND_headless", XR_EXT_HAND_TRACKING_EXTENSION_NAME});
  ASSERT_NE(instance, XR_NULL_HANDLE);
  for (const char* name : hands) EXPECT_EQ(lookUp(instance, name), XR_SUCCESS) << name;
  for (const char* name : vulkan)
    EXPECT_EQ(lookUp(instance, name), XR_ERROR_FUNCTION_UNSUPPORTED) << name;
  destroyInstance(instance);

  instance = createInstance({"XR_KHR_vulkan_enable2"});
  ASSERT_NE(instance, XR_NULL_HANDLE);
  for (const char* name : vulkan) EXPECT_EQ(lookUp(instance, name), XR_SUCCESS) << name;
  destroyInstance(instance);
}

}  // namespace
