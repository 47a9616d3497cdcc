// The simulated OpenXR runtime's shared state and helpers, for its four parts split along the
// specification's chapters: runtime_instance.cpp (instance, paths, system, dispatch),
// runtime_session.cpp (session, state machine, frames), runtime_input.cpp (spaces, actions) and
// runtime_swapchains.cpp (swapchains, XR_KHR_vulkan_enable2). Private to the runtime library (its
// symbols are hidden); runtime_state.cpp holds the definitions. See runtime_state.cpp's opening
// comment for what the runtime does.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstring>
#include <deque>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/gtc/quaternion.hpp>
#define XR_USE_GRAPHICS_API_VULKAN
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
#include <openxr/openxr_reflection.h>

#include "interaction/xr_controls.hpp"
#include "sim_input/simulated_hand.hpp"
#include "sim_input/xr_runtime/loader_negotiation.hpp"
#include "sim_input/xr_runtime/profile_paths.hpp"
#include "sim_input/xr_runtime/sim_user.hpp"
#include "sim_input/xr_runtime/vulkan_images.hpp"

namespace curvefold::simxr {

constexpr XrSystemId kSystemId = 1;
// Layers a swapchain may have (arraySize): enough for a multiview app's two eyes and more.
constexpr std::uint32_t kMaxSwapchainLayers = 16;
constexpr const char* kProfilePreference[] = {"/interaction_profiles/oculus/touch_controller",
                                              "/interaction_profiles/valve/index_controller",
                                              "/interaction_profiles/htc/vive_controller",
                                              "/interaction_profiles/microsoft/motion_controller",
                                              "/interaction_profiles/khr/simple_controller"};

struct Session;
struct ActionSet;

struct Action {
  ActionSet* set = nullptr;
  std::string name;
  XrActionType type = XR_ACTION_TYPE_BOOLEAN_INPUT;
  std::vector<XrPath> subactions;
  // After the last sync, per hand: value, the value before it, when it changed.
  std::array<float, 2> value{}, previous{};
  std::array<bool, 2> active{};
  std::array<XrTime, 2> changed{};
};

struct ActionSet {
  std::string name;
  std::vector<std::unique_ptr<Action>> actions;
  bool attached = false;
};

struct Space {
  Session* session = nullptr;
  XrReferenceSpaceType reference = XR_REFERENCE_SPACE_TYPE_STAGE;
  Action* action = nullptr;  // an action space when set
  XrPath subaction = XR_NULL_PATH;
  Pose offset;
};

// An XR_EXT_hand_tracking tracker: one hand of one session.
struct HandTracker {
  Session* session = nullptr;
  int hand = 0;  // 0 left, 1 right
};

struct Swapchain {
  Session* session = nullptr;
  std::unique_ptr<SwapchainImages> images;
  std::deque<std::uint32_t> acquired;  // in acquire order
  bool waited = false;
  std::uint32_t next = 0;
  std::int64_t lastReleased = -1;
};

struct Session {
  std::optional<VulkanBinding> vulkan;  // none: headless
  XrSessionState state = XR_SESSION_STATE_IDLE;
  bool running = false, exitRequested = false, lost = false, focusedOnce = false;
  bool waited = false, begun = false;
  std::set<Space*> spaces;
  std::set<Swapchain*> swapchains;
  std::set<HandTracker*> handTrackers;
  struct ViewImage {
    Swapchain* swapchain = nullptr;
    std::uint32_t layer = 0;  // imageArrayIndex
  };
  std::map<std::uint32_t, ViewImage> lastViewSwapchain;  // view -> last submitted
  bool syncedFocused = false;
  bool attached = false;  // action sets attached (once per session)
};

struct Instance {
  SimConfig config;
  std::set<std::string> extensions;
  std::vector<std::string> paths{""};  // XrPath = index; 0 is XR_NULL_PATH
  std::map<std::string, XrPath, std::less<>> pathIds;
  std::set<std::unique_ptr<ActionSet>> actionSets;
  std::map<std::string, std::vector<std::pair<Action*, std::string>>> bindings;  // by profile
  std::set<Session*> sessions;
  std::deque<XrEventDataBuffer> events;
  bool lossPending = false, lost = false, requirementsCalled = false;
  int unavailableSystems = 0;  // xrGetSystem failures left after a session loss
  std::string profile;         // current, both hands
  // Serving.
  std::size_t nextFrame = 0;
  std::optional<std::size_t> served;
  std::optional<SimUser> user;
  std::array<HandState, 2> hands;
  // Hands tracked instead of controllers (CURVEFOLD_SIM_HANDS, the hands and controllers events)
  // and their joints this frame, jittered once when the frame is served.
  bool servingHands = false;
  std::array<HandJoints, 2> handJoints;
  std::mt19937_64 random{1};
  XrTime time = 1'000'000'000;
  std::chrono::steady_clock::time_point wallStart;
  std::ofstream log;
};

// The one instance there may be, and every live handle of every type (handles are checked).
extern Instance* gInstance;
extern std::set<void*> gHandles;

template <typename Handle, typename T>
Handle handleOf(T* object) {
  gHandles.insert(object);
  return reinterpret_cast<Handle>(object);
}
template <typename T, typename Handle>
T* objectOf(Handle handle) {
  void* p = reinterpret_cast<void*>(handle);
  return p && gHandles.count(p) ? static_cast<T*>(p) : nullptr;
}

// An entry point's error, thrown by the helpers and turned into its XrResult by guard().
struct Failure {
  XrResult result;
};
[[noreturn]] void fail(XrResult result);

template <typename T>
void checkType(const T* structure, XrStructureType type) {
  if (!structure) fail(XR_ERROR_VALIDATION_FAILURE);
  if (structure->type != type) fail(XR_ERROR_VALIDATION_FAILURE);
}

// The two-call idiom.
template <typename T>
void fill(const std::vector<T>& values, std::uint32_t capacity, std::uint32_t* count, T* out) {
  if (!count) fail(XR_ERROR_VALIDATION_FAILURE);
  *count = static_cast<std::uint32_t>(values.size());
  if (capacity == 0) return;
  if (capacity < values.size()) fail(XR_ERROR_SIZE_INSUFFICIENT);
  std::copy(values.begin(), values.end(), out);
}

Instance& instanceOf(XrInstance handle);
Session& sessionOf(XrSession handle);
Session& liveSessionOf(XrSession handle);
void log(const std::string& line);
const std::string& pathString(Instance& instance, XrPath path);
const char* stateName(XrSessionState state);
void pushEvent(Instance& instance, const void* event, std::size_t size);
void setState(Session& session, XrSessionState state);
// Runtime-requested or app-requested end: down through the states to STOPPING.
void stop(Session& session);
void profileChanged(Instance& instance, Session& session);
// The profile the user's controllers show: the forced one or the first suggested of the
// preference order; none while hands are served.
std::string chosenProfile(const Instance& instance);
// The value of an action on a hand through the current profile's bindings.
std::optional<float> resolve(Instance& instance, const Action& action, int hand);
int handIndex(Instance& instance, XrPath path);
void serveFrame(Instance& instance, Session& session);
Pose locate(Instance& instance, const Space& space, bool& valid);
XrPosef toXr(const Pose& pose);
Pose fromXr(const XrPosef& p);
void saveViews(Session& session, Swapchain* only = nullptr);
void destroySwapchain(Swapchain* swapchain);
void destroyHandTracker(HandTracker* tracker);
void destroySession(Session* session);
void checkSystem(XrSystemId system);

// ---------------------------------------------------------------------------------------------
// Entry points. Each body runs in guard(), which turns failures and exceptions into results.

template <typename Body>
XrResult guard(Body body) {
  try {
    return body();
  } catch (const Failure& failure) {
    return failure.result;
  } catch (const std::exception& e) {
    std::cerr << "curvefold sim runtime: " << e.what() << std::endl;
    return XR_ERROR_RUNTIME_FAILURE;
  } catch (...) {
    return XR_ERROR_RUNTIME_FAILURE;
  }
}

// The entry points, for the dispatch table.
XRAPI_ATTR XrResult XRAPI_CALL getInstanceProcAddr(XrInstance instance, const char* name,
                                                   PFN_xrVoidFunction* function);
XRAPI_ATTR XrResult XRAPI_CALL enumerateInstanceExtensionProperties(const char* layer,
                                                                    std::uint32_t capacity,
                                                                    std::uint32_t* count,
                                                                    XrExtensionProperties* out);
XRAPI_ATTR XrResult XRAPI_CALL createInstance(const XrInstanceCreateInfo* info, XrInstance* out);
XRAPI_ATTR XrResult XRAPI_CALL destroyInstance(XrInstance handle);
XRAPI_ATTR XrResult XRAPI_CALL getInstanceProperties(XrInstance handle,
                                                     XrInstanceProperties* properties);
XRAPI_ATTR XrResult XRAPI_CALL resultToString(XrInstance handle, XrResult value,
                                              char buffer[XR_MAX_RESULT_STRING_SIZE]);
XRAPI_ATTR XrResult XRAPI_CALL structureTypeToString(XrInstance handle, XrStructureType value,
                                                     char buffer[XR_MAX_STRUCTURE_NAME_SIZE]);
XRAPI_ATTR XrResult XRAPI_CALL pollEvent(XrInstance handle, XrEventDataBuffer* event);
XRAPI_ATTR XrResult XRAPI_CALL stringToPath(XrInstance handle, const char* text, XrPath* path);
XRAPI_ATTR XrResult XRAPI_CALL pathToString(XrInstance handle, XrPath path, std::uint32_t capacity,
                                            std::uint32_t* count, char* buffer);
XRAPI_ATTR XrResult XRAPI_CALL getSystem(XrInstance handle, const XrSystemGetInfo* info,
                                         XrSystemId* system);
XRAPI_ATTR XrResult XRAPI_CALL getSystemProperties(XrInstance handle, XrSystemId system,
                                                   XrSystemProperties* properties);
XRAPI_ATTR XrResult XRAPI_CALL enumerateViewConfigurations(XrInstance handle, XrSystemId system,
                                                           std::uint32_t capacity,
                                                           std::uint32_t* count,
                                                           XrViewConfigurationType* out);
XRAPI_ATTR XrResult XRAPI_CALL
getViewConfigurationProperties(XrInstance handle, XrSystemId system, XrViewConfigurationType type,
                               XrViewConfigurationProperties* properties);
XRAPI_ATTR XrResult XRAPI_CALL enumerateViewConfigurationViews(XrInstance handle, XrSystemId system,
                                                               XrViewConfigurationType type,
                                                               std::uint32_t capacity,
                                                               std::uint32_t* count,
                                                               XrViewConfigurationView* out);
XRAPI_ATTR XrResult XRAPI_CALL enumerateEnvironmentBlendModes(XrInstance handle, XrSystemId system,
                                                              XrViewConfigurationType,
                                                              std::uint32_t capacity,
                                                              std::uint32_t* count,
                                                              XrEnvironmentBlendMode* out);
XRAPI_ATTR XrResult XRAPI_CALL createSession(XrInstance handle, const XrSessionCreateInfo* info,
                                             XrSession* out);
XRAPI_ATTR XrResult XRAPI_CALL destroySessionEntry(XrSession handle);
XRAPI_ATTR XrResult XRAPI_CALL beginSession(XrSession handle, const XrSessionBeginInfo* info);
XRAPI_ATTR XrResult XRAPI_CALL endSession(XrSession handle);
XRAPI_ATTR XrResult XRAPI_CALL requestExitSession(XrSession handle);
XRAPI_ATTR XrResult XRAPI_CALL locateViews(XrSession handle, const XrViewLocateInfo* info,
                                           XrViewState* state, std::uint32_t capacity,
                                           std::uint32_t* count, XrView* views);
XRAPI_ATTR XrResult XRAPI_CALL waitFrame(XrSession handle, const XrFrameWaitInfo*,
                                         XrFrameState* state);
XRAPI_ATTR XrResult XRAPI_CALL beginFrame(XrSession handle, const XrFrameBeginInfo*);
XRAPI_ATTR XrResult XRAPI_CALL endFrame(XrSession handle, const XrFrameEndInfo* info);
XRAPI_ATTR XrResult XRAPI_CALL enumerateReferenceSpaces(XrSession handle, std::uint32_t capacity,
                                                        std::uint32_t* count,
                                                        XrReferenceSpaceType* out);
XRAPI_ATTR XrResult XRAPI_CALL createReferenceSpace(XrSession handle,
                                                    const XrReferenceSpaceCreateInfo* info,
                                                    XrSpace* out);
XRAPI_ATTR XrResult XRAPI_CALL getReferenceSpaceBoundsRect(XrSession handle,
                                                           XrReferenceSpaceType type,
                                                           XrExtent2Df* bounds);
XRAPI_ATTR XrResult XRAPI_CALL createActionSpace(XrSession handle,
                                                 const XrActionSpaceCreateInfo* info, XrSpace* out);
XRAPI_ATTR XrResult XRAPI_CALL locateSpace(XrSpace spaceHandle, XrSpace baseHandle, XrTime,
                                           XrSpaceLocation* location);
XRAPI_ATTR XrResult XRAPI_CALL destroySpace(XrSpace handle);
XRAPI_ATTR XrResult XRAPI_CALL createActionSet(XrInstance handle, const XrActionSetCreateInfo* info,
                                               XrActionSet* out);
XRAPI_ATTR XrResult XRAPI_CALL destroyActionSet(XrActionSet handle);
XRAPI_ATTR XrResult XRAPI_CALL createAction(XrActionSet handle, const XrActionCreateInfo* info,
                                            XrAction* out);
XRAPI_ATTR XrResult XRAPI_CALL destroyAction(XrAction handle);
XRAPI_ATTR XrResult XRAPI_CALL
suggestBindings(XrInstance handle, const XrInteractionProfileSuggestedBinding* suggested);
XRAPI_ATTR XrResult XRAPI_CALL attachActionSets(XrSession handle,
                                                const XrSessionActionSetsAttachInfo* info);
XRAPI_ATTR XrResult XRAPI_CALL getCurrentInteractionProfile(XrSession handle, XrPath user,
                                                            XrInteractionProfileState* state);
XRAPI_ATTR XrResult XRAPI_CALL syncActions(XrSession handle, const XrActionsSyncInfo* info);
XRAPI_ATTR XrResult XRAPI_CALL getActionStateBoolean(XrSession handle,
                                                     const XrActionStateGetInfo* info,
                                                     XrActionStateBoolean* state);
XRAPI_ATTR XrResult XRAPI_CALL getActionStateFloat(XrSession handle,
                                                   const XrActionStateGetInfo* info,
                                                   XrActionStateFloat* state);
XRAPI_ATTR XrResult XRAPI_CALL getActionStateVector2f(XrSession handle,
                                                      const XrActionStateGetInfo* info,
                                                      XrActionStateVector2f* state);
XRAPI_ATTR XrResult XRAPI_CALL getActionStatePose(XrSession handle,
                                                  const XrActionStateGetInfo* info,
                                                  XrActionStatePose* state);
XRAPI_ATTR XrResult XRAPI_CALL applyHapticFeedback(XrSession handle, const XrHapticActionInfo* info,
                                                   const XrHapticBaseHeader* haptic);
XRAPI_ATTR XrResult XRAPI_CALL stopHapticFeedback(XrSession handle, const XrHapticActionInfo* info);
XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainFormats(XrSession handle, std::uint32_t capacity,
                                                         std::uint32_t* count, std::int64_t* out);
XRAPI_ATTR XrResult XRAPI_CALL createSwapchain(XrSession handle, const XrSwapchainCreateInfo* info,
                                               XrSwapchain* out);
XRAPI_ATTR XrResult XRAPI_CALL destroySwapchainEntry(XrSwapchain handle);
XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainImages(XrSwapchain handle, std::uint32_t capacity,
                                                        std::uint32_t* count,
                                                        XrSwapchainImageBaseHeader* out);
XRAPI_ATTR XrResult XRAPI_CALL acquireSwapchainImage(XrSwapchain handle,
                                                     const XrSwapchainImageAcquireInfo*,
                                                     std::uint32_t* index);
XRAPI_ATTR XrResult XRAPI_CALL waitSwapchainImage(XrSwapchain handle,
                                                  const XrSwapchainImageWaitInfo* info);
XRAPI_ATTR XrResult XRAPI_CALL releaseSwapchainImage(XrSwapchain handle,
                                                     const XrSwapchainImageReleaseInfo*);
XRAPI_ATTR XrResult XRAPI_CALL createHandTracker(XrSession handle,
                                                 const XrHandTrackerCreateInfoEXT* info,
                                                 XrHandTrackerEXT* out);
XRAPI_ATTR XrResult XRAPI_CALL destroyHandTrackerEntry(XrHandTrackerEXT handle);
XRAPI_ATTR XrResult XRAPI_CALL locateHandJoints(XrHandTrackerEXT handle,
                                                const XrHandJointsLocateInfoEXT* info,
                                                XrHandJointLocationsEXT* locations);
XRAPI_ATTR XrResult XRAPI_CALL getVulkanGraphicsRequirements2(
    XrInstance handle, XrSystemId system, XrGraphicsRequirementsVulkanKHR* requirements);
XRAPI_ATTR XrResult XRAPI_CALL createVulkanInstance(XrInstance handle,
                                                    const XrVulkanInstanceCreateInfoKHR* info,
                                                    VkInstance* vulkan, VkResult* result);
XRAPI_ATTR XrResult XRAPI_CALL getVulkanGraphicsDevice2(
    XrInstance handle, const XrVulkanGraphicsDeviceGetInfoKHR* info, VkPhysicalDevice* device);
XRAPI_ATTR XrResult XRAPI_CALL createVulkanDevice(XrInstance handle,
                                                  const XrVulkanDeviceCreateInfoKHR* info,
                                                  VkDevice* vulkan, VkResult* result);

}  // namespace curvefold::simxr
