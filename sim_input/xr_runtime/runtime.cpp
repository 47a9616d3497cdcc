// The simulated OpenXR runtime (docs/design.md 6): a shared library the Khronos loader loads
// through XR_RUNTIME_JSON (the manifest is generated beside it). It serves a head and two
// controllers from a recording, frame-locked (one recorded frame per focused xrWaitFrame), runs the
// session state machine a real runtime runs, resolves actions through the application's suggested
// bindings for the current interaction profile, and makes XR_KHR_vulkan_enable2 swapchains on the
// application's device (XR_MND_headless sessions have none) in sRGB and UNORM colour formats and
// the device's depth formats, and takes depth images with XR_KHR_composition_layer_depth. Its log
// names each swapchain's format and, per frame, how many views came with depth. sim_user.hpp lists
// its settings.
//
// One instance at a time; every entry point validates its handles and structure types and
// catches exceptions at the C boundary.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <deque>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
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
#include "sim_input/xr_runtime/loader_negotiation.hpp"
#include "sim_input/xr_runtime/profile_paths.hpp"
#include "sim_input/xr_runtime/sim_user.hpp"
#include "sim_input/xr_runtime/vulkan_images.hpp"

namespace curvefold::simxr {
namespace {

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
  XrTime time = 1'000'000'000;
  std::chrono::steady_clock::time_point wallStart;
  std::ofstream log;
};

Instance* gInstance = nullptr;
std::set<void*> gHandles;  // every live handle of every type

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

struct Failure {
  XrResult result;
};
[[noreturn]] void fail(XrResult result) {
  throw Failure{result};
}

Instance& instanceOf(XrInstance handle) {
  Instance* instance = objectOf<Instance>(handle);
  if (!instance || instance != gInstance) fail(XR_ERROR_HANDLE_INVALID);
  if (instance->lost) fail(XR_ERROR_INSTANCE_LOST);
  return *instance;
}
Session& sessionOf(XrSession handle) {
  Session* session = objectOf<Session>(handle);
  if (!session || !gInstance || !gInstance->sessions.count(session)) fail(XR_ERROR_HANDLE_INVALID);
  if (gInstance->lost) fail(XR_ERROR_INSTANCE_LOST);
  return *session;
}
Session& liveSessionOf(XrSession handle) {
  Session& session = sessionOf(handle);
  if (session.lost) fail(XR_ERROR_SESSION_LOST);
  return session;
}

void log(const std::string& line) {
  if (gInstance && gInstance->log.is_open()) gInstance->log << line << std::endl;
}

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

const std::string& pathString(Instance& instance, XrPath path) {
  if (path == XR_NULL_PATH || path >= instance.paths.size()) fail(XR_ERROR_PATH_INVALID);
  return instance.paths[path];
}

const char* stateName(XrSessionState state) {
  switch (state) {
#define CURVEFOLD_SIM_STATE(name, value) \
  case name:                             \
    return &#name[17];  // after "XR_SESSION_STATE_"
    XR_LIST_ENUM_XrSessionState(CURVEFOLD_SIM_STATE)
#undef CURVEFOLD_SIM_STATE
        default : return "?";
  }
}

void pushEvent(Instance& instance, const void* event, std::size_t size) {
  XrEventDataBuffer buffer{XR_TYPE_EVENT_DATA_BUFFER};
  std::memcpy(&buffer, event, size);
  instance.events.push_back(buffer);
}

void setState(Session& session, XrSessionState state) {
  session.state = state;
  XrEventDataSessionStateChanged event{XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED};
  event.session = reinterpret_cast<XrSession>(&session);
  event.state = state;
  event.time = gInstance->time;
  pushEvent(*gInstance, &event, sizeof event);
  log(std::string("state ") + stateName(state));
}

// Runtime-requested or app-requested end: down through the states to STOPPING.
void stop(Session& session) {
  if (!session.running || session.state == XR_SESSION_STATE_STOPPING) return;
  if (session.state == XR_SESSION_STATE_FOCUSED) setState(session, XR_SESSION_STATE_VISIBLE);
  if (session.state == XR_SESSION_STATE_VISIBLE) setState(session, XR_SESSION_STATE_SYNCHRONIZED);
  setState(session, XR_SESSION_STATE_STOPPING);
}

void profileChanged(Instance& instance, Session& session) {
  XrEventDataInteractionProfileChanged event{XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED};
  event.session = reinterpret_cast<XrSession>(&session);
  pushEvent(instance, &event, sizeof event);
  log("profile " + instance.profile);
}

// The value of an action on a hand through the current profile's bindings.
std::optional<float> resolve(Instance& instance, const Action& action, int hand) {
  const auto found = instance.bindings.find(instance.profile);
  if (found == instance.bindings.end()) return std::nullopt;
  std::optional<float> value;
  for (const auto& [bound, path] : found->second) {
    if (bound != &action) continue;
    std::string component;
    if (handOf(path, &component) != hand) continue;
    const auto& inputs = instance.hands[hand].inputs;
    // Several sources of one action: the largest magnitude wins (an axis may be negative).
    auto larger = [](float a, float b) { return std::abs(b) > std::abs(a) ? b : a; };
    float v = 0.0f;
    for (const std::string& key :
         {component, component + "/value", component + "/click", component + "/force"})
      if (auto it = inputs.find(key); it != inputs.end()) v = larger(v, it->second);
    if (action.type == XR_ACTION_TYPE_BOOLEAN_INPUT) v = v >= 0.5f ? 1.0f : 0.0f;
    value = larger(value.value_or(0.0f), v);
  }
  return value;
}

int handIndex(Instance& instance, XrPath path) {
  if (path == XR_NULL_PATH) return -1;
  const int hand = handOf(pathString(instance, path));
  if (hand < 0) fail(XR_ERROR_PATH_UNSUPPORTED);
  return hand;
}

void serveFrame(Instance& instance, Session& session) {
  const SimConfig& config = instance.config;
  const XrDuration period =
      config.input ? XrDuration(1e9 / std::max(config.input->header.rate, 1.0)) : 11'111'111;
  if (!config.input || session.state != XR_SESSION_STATE_FOCUSED) {
    instance.time += period;
    return;
  }
  const auto& frames = config.input->frames;
  if (instance.nextFrame >= frames.size()) {
    instance.time += period;
    if (!config.hold) {
      session.exitRequested = true;
      stop(session);
    }
    return;
  }
  const std::size_t index = instance.nextFrame++;
  XrDuration step = period;
  if (instance.served)
    step = std::max<XrDuration>(
        1, XrDuration((frames[index].time - frames[*instance.served].time) * 1e9));
  instance.served = index;
  instance.time += step;
  instance.hands = instance.user->controllersFor(frames[index], instance.profile);
  log("frame " + std::to_string(index));
  if (auto events = config.events.find(index); events != config.events.end())
    for (const std::string& event : events->second) {
      log("event " + event);
      if (event == "loss_pending") {
        // The session works until the application has seen the event, then it is lost.
        setState(session, XR_SESSION_STATE_LOSS_PENDING);
        instance.unavailableSystems = 2;
      } else if (event == "instance_loss") {
        XrEventDataInstanceLossPending loss{XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING};
        loss.lossTime = instance.time;
        pushEvent(instance, &loss, sizeof loss);
        instance.lossPending = true;
      } else if (event == "exit") {
        session.exitRequested = true;
        stop(session);
      } else if (event.starts_with("profile=")) {
        instance.profile = event.substr(8);
        profileChanged(instance, session);
      }
    }
}

Pose locate(Instance& instance, const Space& space, bool& valid) {
  valid = true;
  if (space.action) {
    const int hand = space.subaction == XR_NULL_PATH ? 0 : handIndex(instance, space.subaction);
    valid = instance.hands[hand].tracked && resolve(instance, *space.action, hand).has_value() &&
            space.session->state == XR_SESSION_STATE_FOCUSED;
    return instance.hands[hand].pose * space.offset;
  }
  if (space.reference == XR_REFERENCE_SPACE_TYPE_VIEW) {
    const Pose sheet =
        instance.config.input ? instance.config.input->header.sheetFrame : defaultSheetFrame();
    return headPoseFor(sheet) * space.offset;
  }
  return space.offset;  // stage and local: the recording's world
}

XrPosef toXr(const Pose& pose) {
  XrPosef p;
  p.position = {float(pose.position.x), float(pose.position.y), float(pose.position.z)};
  p.orientation = {float(pose.orientation.x), float(pose.orientation.y), float(pose.orientation.z),
                   float(pose.orientation.w)};
  return p;
}
Pose fromXr(const XrPosef& p) {
  return {{p.position.x, p.position.y, p.position.z},
          glm::normalize(
              glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z))};
}

void saveViews(Session& session, Swapchain* only = nullptr) {
  if (!gInstance || gInstance->config.saveViews.empty()) return;
  // Views may share an array swapchain (a layer each): every view is saved before any image is
  // marked as saved.
  std::vector<Swapchain*> saved;
  for (auto& [view, image] : session.lastViewSwapchain) {
    Swapchain* swapchain = image.swapchain;
    if (!swapchain || (only && swapchain != only) || swapchain->lastReleased < 0) continue;
    const std::string name = "view" + std::to_string(view) + ".png";
    swapchain->images->savePng(std::uint32_t(swapchain->lastReleased), image.layer,
                               std::filesystem::path(gInstance->config.saveViews) / name);
    log("saved " + name);
    saved.push_back(swapchain);
  }
  for (Swapchain* swapchain : saved) swapchain->lastReleased = -1;
}

void destroySwapchain(Swapchain* swapchain) {
  saveViews(*swapchain->session, swapchain);
  for (auto& [view, last] : swapchain->session->lastViewSwapchain)
    if (last.swapchain == swapchain) last.swapchain = nullptr;
  swapchain->session->swapchains.erase(swapchain);
  gHandles.erase(swapchain);
  delete swapchain;
}

void destroySession(Session* session) {
  // Its pending events die with it (a new session may get the same handle value).
  std::erase_if(gInstance->events, [&](const XrEventDataBuffer& event) {
    const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
    return (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED ||
            event.type == XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED) &&
           changed.session == reinterpret_cast<XrSession>(session);
  });
  for (Swapchain* swapchain : std::set<Swapchain*>(session->swapchains))
    destroySwapchain(swapchain);
  for (Space* space : session->spaces) {
    gHandles.erase(space);
    delete space;
  }
  gInstance->sessions.erase(session);
  gHandles.erase(session);
  delete session;
}

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

const char* const kExtensions[] = {"XR_KHR_vulkan_enable2", "XR_MND_headless",
                                   "XR_KHR_composition_layer_depth"};

XRAPI_ATTR XrResult XRAPI_CALL enumerateInstanceExtensionProperties(const char* layer,
                                                                    std::uint32_t capacity,
                                                                    std::uint32_t* count,
                                                                    XrExtensionProperties* out) {
  return guard([&] {
    if (layer) return XR_ERROR_API_LAYER_NOT_PRESENT;
    std::vector<XrExtensionProperties> all;
    for (const char* name : kExtensions) {
      XrExtensionProperties p{XR_TYPE_EXTENSION_PROPERTIES};
      std::strncpy(p.extensionName, name, XR_MAX_EXTENSION_NAME_SIZE - 1);
      p.extensionVersion = 1;
      all.push_back(p);
    }
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = std::uint32_t(all.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < all.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    for (std::size_t i = 0; i < all.size(); ++i) {
      checkType(&out[i], XR_TYPE_EXTENSION_PROPERTIES);
      std::memcpy(out[i].extensionName, all[i].extensionName, XR_MAX_EXTENSION_NAME_SIZE);
      out[i].extensionVersion = all[i].extensionVersion;
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createInstance(const XrInstanceCreateInfo* info, XrInstance* out) {
  return guard([&] {
    checkType(info, XR_TYPE_INSTANCE_CREATE_INFO);
    if (!out) return XR_ERROR_VALIDATION_FAILURE;
    if (gInstance) return XR_ERROR_LIMIT_REACHED;
    auto instance = std::make_unique<Instance>();
    for (std::uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
      const std::string name = info->enabledExtensionNames[i];
      if (std::find(std::begin(kExtensions), std::end(kExtensions), name) == std::end(kExtensions))
        return XR_ERROR_EXTENSION_NOT_PRESENT;
      instance->extensions.insert(name);
    }
    try {
      instance->config = SimConfig::fromEnvironment();
    } catch (const std::exception& e) {
      std::cerr << "curvefold sim runtime: " << e.what() << std::endl;
      return XR_ERROR_RUNTIME_FAILURE;
    }
    if (!instance->config.logPath.empty())
      instance->log.open(instance->config.logPath, std::ios::app);
    if (instance->config.input)
      instance->user.emplace(instance->config.input->header.handedness);
    else
      instance->user.emplace(Handedness::Right);
    instance->wallStart = std::chrono::steady_clock::now();
    gInstance = instance.release();
    *out = handleOf<XrInstance>(gInstance);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroyInstance(XrInstance handle) {
  return guard([&] {
    Instance* instance = objectOf<Instance>(handle);
    if (!instance || instance != gInstance) return XR_ERROR_HANDLE_INVALID;
    for (Session* session : std::set<Session*>(instance->sessions)) destroySession(session);
    for (const auto& set : instance->actionSets) {
      for (const auto& action : set->actions) gHandles.erase(action.get());
      gHandles.erase(set.get());
    }
    gHandles.erase(instance);
    gInstance = nullptr;
    delete instance;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getInstanceProperties(XrInstance handle,
                                                     XrInstanceProperties* properties) {
  return guard([&] {
    instanceOf(handle);
    checkType(properties, XR_TYPE_INSTANCE_PROPERTIES);
    properties->runtimeVersion = XR_MAKE_VERSION(0, 1, 0);
    std::strncpy(properties->runtimeName, "curvefold simulated runtime",
                 XR_MAX_RUNTIME_NAME_SIZE - 1);
    return XR_SUCCESS;
  });
}

// A name into a fixed-size, always terminated buffer.
void writeName(const std::string& name, char* buffer, std::size_t size) {
  std::strncpy(buffer, name.c_str(), size - 1);
  buffer[size - 1] = '\0';
}

XRAPI_ATTR XrResult XRAPI_CALL resultToString(XrInstance handle, XrResult value,
                                              char buffer[XR_MAX_RESULT_STRING_SIZE]) {
  return guard([&] {
    instanceOf(handle);
    const char* name = nullptr;
    switch (value) {
#define CURVEFOLD_SIM_RESULT(n, v) \
  case n:                          \
    name = #n;                     \
    break;
      XR_LIST_ENUM_XrResult(CURVEFOLD_SIM_RESULT)
#undef CURVEFOLD_SIM_RESULT
          default : break;
    }
    writeName(name ? name : "XR_UNKNOWN_" + std::to_string(int(value)), buffer,
              XR_MAX_RESULT_STRING_SIZE);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL structureTypeToString(XrInstance handle, XrStructureType value,
                                                     char buffer[XR_MAX_STRUCTURE_NAME_SIZE]) {
  return guard([&] {
    instanceOf(handle);
    const char* name = nullptr;
    switch (value) {
#define CURVEFOLD_SIM_TYPE(n, v) \
  case n:                        \
    name = #n;                   \
    break;
      XR_LIST_ENUM_XrStructureType(CURVEFOLD_SIM_TYPE)
#undef CURVEFOLD_SIM_TYPE
          default : break;
    }
    writeName(name ? name : "XR_UNKNOWN_STRUCTURE_TYPE_" + std::to_string(int(value)), buffer,
              XR_MAX_STRUCTURE_NAME_SIZE);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL pollEvent(XrInstance handle, XrEventDataBuffer* event) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkType(event, XR_TYPE_EVENT_DATA_BUFFER);
    if (instance.events.empty()) return XR_EVENT_UNAVAILABLE;
    *event = instance.events.front();
    instance.events.pop_front();
    // Once the application has seen a loss, the instance or session is gone.
    if (event->type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) instance.lost = true;
    if (event->type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(*event);
      Session* session = objectOf<Session>(changed.session);
      if (changed.state == XR_SESSION_STATE_LOSS_PENDING && session) {
        session->lost = true;
        session->running = false;
      }
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL stringToPath(XrInstance handle, const char* text, XrPath* path) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    if (!text || !path) return XR_ERROR_VALIDATION_FAILURE;
    const std::string s = text;
    if (s.empty() || s[0] != '/' || s.back() == '/' || s.find("//") != std::string::npos ||
        s.size() >= XR_MAX_PATH_LENGTH)
      return XR_ERROR_PATH_FORMAT_INVALID;
    if (auto found = instance.pathIds.find(s); found != instance.pathIds.end()) {
      *path = found->second;
      return XR_SUCCESS;
    }
    instance.paths.push_back(s);
    *path = instance.paths.size() - 1;
    instance.pathIds[s] = *path;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL pathToString(XrInstance handle, XrPath path, std::uint32_t capacity,
                                            std::uint32_t* count, char* buffer) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    const std::string& text = pathString(instance, path);
    std::vector<char> chars(text.begin(), text.end());
    chars.push_back('\0');
    fill(chars, capacity, count, buffer);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getSystem(XrInstance handle, const XrSystemGetInfo* info,
                                         XrSystemId* system) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkType(info, XR_TYPE_SYSTEM_GET_INFO);
    if (!system) return XR_ERROR_VALIDATION_FAILURE;
    if (info->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY)
      return XR_ERROR_FORM_FACTOR_UNSUPPORTED;
    if (instance.config.noHmd) return XR_ERROR_FORM_FACTOR_UNAVAILABLE;
    if (instance.unavailableSystems > 0) {
      --instance.unavailableSystems;  // the headset reconnecting after a loss
      return XR_ERROR_FORM_FACTOR_UNAVAILABLE;
    }
    *system = kSystemId;
    return XR_SUCCESS;
  });
}

void checkSystem(XrSystemId system) {
  if (system != kSystemId) fail(XR_ERROR_SYSTEM_INVALID);
}

XRAPI_ATTR XrResult XRAPI_CALL getSystemProperties(XrInstance handle, XrSystemId system,
                                                   XrSystemProperties* properties) {
  return guard([&] {
    instanceOf(handle);
    checkSystem(system);
    checkType(properties, XR_TYPE_SYSTEM_PROPERTIES);
    properties->systemId = system;
    properties->vendorId = 0;
    std::strncpy(properties->systemName, "curvefold simulated headset",
                 XR_MAX_SYSTEM_NAME_SIZE - 1);
    properties->graphicsProperties.maxLayerCount = 16;
    properties->graphicsProperties.maxSwapchainImageWidth = 4096;
    properties->graphicsProperties.maxSwapchainImageHeight = 4096;
    properties->trackingProperties.orientationTracking = XR_TRUE;
    properties->trackingProperties.positionTracking = XR_TRUE;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateViewConfigurations(XrInstance handle, XrSystemId system,
                                                           std::uint32_t capacity,
                                                           std::uint32_t* count,
                                                           XrViewConfigurationType* out) {
  return guard([&] {
    instanceOf(handle);
    checkSystem(system);
    fill(std::vector<XrViewConfigurationType>{XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO}, capacity,
         count, out);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL
getViewConfigurationProperties(XrInstance handle, XrSystemId system, XrViewConfigurationType type,
                               XrViewConfigurationProperties* properties) {
  return guard([&] {
    instanceOf(handle);
    checkSystem(system);
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
      return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    checkType(properties, XR_TYPE_VIEW_CONFIGURATION_PROPERTIES);
    properties->viewConfigurationType = type;
    properties->fovMutable = XR_FALSE;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateViewConfigurationViews(XrInstance handle, XrSystemId system,
                                                               XrViewConfigurationType type,
                                                               std::uint32_t capacity,
                                                               std::uint32_t* count,
                                                               XrViewConfigurationView* out) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkSystem(system);
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
      return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 2;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
    for (int i = 0; i < 2; ++i) {
      checkType(&out[i], XR_TYPE_VIEW_CONFIGURATION_VIEW);
      out[i].recommendedImageRectWidth = instance.config.viewWidth;
      out[i].recommendedImageRectHeight = instance.config.viewHeight;
      out[i].maxImageRectWidth = out[i].maxImageRectHeight = 4096;
      out[i].recommendedSwapchainSampleCount = 1;
      out[i].maxSwapchainSampleCount = 4;
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateEnvironmentBlendModes(XrInstance handle, XrSystemId system,
                                                              XrViewConfigurationType,
                                                              std::uint32_t capacity,
                                                              std::uint32_t* count,
                                                              XrEnvironmentBlendMode* out) {
  return guard([&] {
    instanceOf(handle);
    checkSystem(system);
    fill(std::vector<XrEnvironmentBlendMode>{XR_ENVIRONMENT_BLEND_MODE_OPAQUE}, capacity, count,
         out);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createSession(XrInstance handle, const XrSessionCreateInfo* info,
                                             XrSession* out) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkType(info, XR_TYPE_SESSION_CREATE_INFO);
    checkSystem(info->systemId);
    if (!out) return XR_ERROR_VALIDATION_FAILURE;
    auto session = std::make_unique<Session>();
    const auto* binding = static_cast<const XrBaseInStructure*>(info->next);
    if (binding && binding->type == XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR) {
      if (!instance.extensions.count("XR_KHR_vulkan_enable2")) return XR_ERROR_VALIDATION_FAILURE;
      if (!instance.requirementsCalled) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
      const auto* vulkan = reinterpret_cast<const XrGraphicsBindingVulkan2KHR*>(binding);
      if (!vulkan->device || !vulkan->physicalDevice || !vulkan->instance)
        return XR_ERROR_GRAPHICS_DEVICE_INVALID;
      session->vulkan = VulkanBinding{vulkan->instance, vulkan->physicalDevice, vulkan->device,
                                      vulkan->queueFamilyIndex, vulkan->queueIndex};
    } else if (!instance.extensions.count("XR_MND_headless")) {
      return XR_ERROR_GRAPHICS_DEVICE_INVALID;
    }
    Session* created = session.release();
    instance.sessions.insert(created);
    *out = handleOf<XrSession>(created);
    setState(*created, XR_SESSION_STATE_IDLE);
    setState(*created, XR_SESSION_STATE_READY);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroySessionEntry(XrSession handle) {
  return guard([&] {
    Session* session = objectOf<Session>(handle);
    if (!session || !gInstance || !gInstance->sessions.count(session))
      return XR_ERROR_HANDLE_INVALID;
    destroySession(session);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL beginSession(XrSession handle, const XrSessionBeginInfo* info) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_SESSION_BEGIN_INFO);
    if (info->primaryViewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
      return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (session.running) return XR_ERROR_SESSION_RUNNING;
    if (session.state != XR_SESSION_STATE_READY) return XR_ERROR_SESSION_NOT_READY;
    session.running = true;
    session.focusedOnce = false;
    setState(session, XR_SESSION_STATE_SYNCHRONIZED);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL endSession(XrSession handle) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (session.state != XR_SESSION_STATE_STOPPING) return XR_ERROR_SESSION_NOT_STOPPING;
    saveViews(session);
    session.running = false;
    session.waited = session.begun = false;
    setState(session, XR_SESSION_STATE_IDLE);
    if (session.exitRequested) setState(session, XR_SESSION_STATE_EXITING);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL requestExitSession(XrSession handle) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    session.exitRequested = true;
    stop(session);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateReferenceSpaces(XrSession handle, std::uint32_t capacity,
                                                        std::uint32_t* count,
                                                        XrReferenceSpaceType* out) {
  return guard([&] {
    sessionOf(handle);
    fill(std::vector<XrReferenceSpaceType>{XR_REFERENCE_SPACE_TYPE_VIEW,
                                           XR_REFERENCE_SPACE_TYPE_LOCAL,
                                           XR_REFERENCE_SPACE_TYPE_STAGE},
         capacity, count, out);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createReferenceSpace(XrSession handle,
                                                    const XrReferenceSpaceCreateInfo* info,
                                                    XrSpace* out) {
  return guard([&] {
    Session& session = sessionOf(handle);
    checkType(info, XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    if (!out) return XR_ERROR_VALIDATION_FAILURE;
    if (info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_VIEW &&
        info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_LOCAL &&
        info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_STAGE)
      return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    auto* space = new Space{&session, info->referenceSpaceType, nullptr, XR_NULL_PATH,
                            fromXr(info->poseInReferenceSpace)};
    session.spaces.insert(space);
    *out = handleOf<XrSpace>(space);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getReferenceSpaceBoundsRect(XrSession handle,
                                                           XrReferenceSpaceType type,
                                                           XrExtent2Df* bounds) {
  return guard([&] {
    sessionOf(handle);
    if (!bounds) return XR_ERROR_VALIDATION_FAILURE;
    if (type != XR_REFERENCE_SPACE_TYPE_STAGE) {
      *bounds = {0.0f, 0.0f};
      return XR_SPACE_BOUNDS_UNAVAILABLE;
    }
    *bounds = {3.0f, 3.0f};
    return XR_SUCCESS;
  });
}

Action& actionOf(XrAction handle) {
  Action* action = objectOf<Action>(handle);
  if (!action) fail(XR_ERROR_HANDLE_INVALID);
  return *action;
}

XRAPI_ATTR XrResult XRAPI_CALL createActionSpace(XrSession handle,
                                                 const XrActionSpaceCreateInfo* info,
                                                 XrSpace* out) {
  return guard([&] {
    Session& session = sessionOf(handle);
    checkType(info, XR_TYPE_ACTION_SPACE_CREATE_INFO);
    Action& action = actionOf(info->action);
    if (action.type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (info->subactionPath != XR_NULL_PATH &&
        std::find(action.subactions.begin(), action.subactions.end(), info->subactionPath) ==
            action.subactions.end())
      return XR_ERROR_PATH_UNSUPPORTED;
    auto* space = new Space{&session, XR_REFERENCE_SPACE_TYPE_STAGE, &action, info->subactionPath,
                            fromXr(info->poseInActionSpace)};
    session.spaces.insert(space);
    *out = handleOf<XrSpace>(space);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL locateSpace(XrSpace spaceHandle, XrSpace baseHandle, XrTime,
                                           XrSpaceLocation* location) {
  return guard([&] {
    Space* space = objectOf<Space>(spaceHandle);
    Space* base = objectOf<Space>(baseHandle);
    if (!space || !base) return XR_ERROR_HANDLE_INVALID;
    liveSessionOf(reinterpret_cast<XrSession>(space->session));
    checkType(location, XR_TYPE_SPACE_LOCATION);
    bool spaceValid = false, baseValid = false;
    const Pose world = locate(*gInstance, *space, spaceValid);
    const Pose worldBase = locate(*gInstance, *base, baseValid);
    location->locationFlags = 0;
    if (spaceValid && baseValid) {
      location->pose = toXr(worldBase.inverse() * world);
      location->locationFlags =
          XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
          XR_SPACE_LOCATION_POSITION_TRACKED_BIT | XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
    } else {
      location->pose = toXr(Pose{});
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroySpace(XrSpace handle) {
  return guard([&] {
    Space* space = objectOf<Space>(handle);
    if (!space) return XR_ERROR_HANDLE_INVALID;
    space->session->spaces.erase(space);
    gHandles.erase(space);
    delete space;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL locateViews(XrSession handle, const XrViewLocateInfo* info,
                                           XrViewState* state, std::uint32_t capacity,
                                           std::uint32_t* count, XrView* views) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_VIEW_LOCATE_INFO);
    checkType(state, XR_TYPE_VIEW_STATE);
    Space* base = objectOf<Space>(info->space);
    if (!base) return XR_ERROR_HANDLE_INVALID;
    if (info->viewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
      return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 2;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
    (void)session;
    bool valid = false;
    const Pose worldBase = locate(*gInstance, *base, valid);
    Space headSpace{&session, XR_REFERENCE_SPACE_TYPE_VIEW, nullptr, XR_NULL_PATH, Pose{}};
    bool headValid = false;
    const Pose head = locate(*gInstance, headSpace, headValid);
    for (int i = 0; i < 2; ++i) {
      checkType(&views[i], XR_TYPE_VIEW);
      const double side = i == 0 ? -0.5 : 0.5;
      const Pose eye = head * Pose{{side * kSimEyeSeparation, 0.0, 0.0}, glm::dquat(1, 0, 0, 0)};
      views[i].pose = toXr(worldBase.inverse() * eye);
      // The left eye sees further left than right (towards the nose less), the right mirrored.
      views[i].fov =
          i == 0 ? XrFovf{-0.87f, 0.79f, 0.84f, -0.91f} : XrFovf{-0.79f, 0.87f, 0.84f, -0.91f};
    }
    state->viewStateFlags =
        valid ? (XR_VIEW_STATE_POSITION_VALID_BIT | XR_VIEW_STATE_ORIENTATION_VALID_BIT |
                 XR_VIEW_STATE_POSITION_TRACKED_BIT | XR_VIEW_STATE_ORIENTATION_TRACKED_BIT)
              : 0;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL waitFrame(XrSession handle, const XrFrameWaitInfo*,
                                         XrFrameState* state) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(state, XR_TYPE_FRAME_STATE);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    Instance& instance = *gInstance;
    serveFrame(instance, session);
    if (instance.config.realtime)
      std::this_thread::sleep_until(instance.wallStart +
                                    std::chrono::nanoseconds(instance.time - 1'000'000'000));
    session.waited = true;
    state->predictedDisplayTime = instance.time;
    state->predictedDisplayPeriod =
        instance.config.input ? XrDuration(1e9 / std::max(instance.config.input->header.rate, 1.0))
                              : 11'111'111;
    state->shouldRender =
        session.state == XR_SESSION_STATE_VISIBLE || session.state == XR_SESSION_STATE_FOCUSED;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL beginFrame(XrSession handle, const XrFrameBeginInfo*) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!session.waited) return XR_ERROR_CALL_ORDER_INVALID;
    session.waited = false;
    const bool discarded = session.begun;
    session.begun = true;
    return discarded ? XR_FRAME_DISCARDED : XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL endFrame(XrSession handle, const XrFrameEndInfo* info) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_FRAME_END_INFO);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!session.begun) return XR_ERROR_CALL_ORDER_INVALID;
    // No xrWaitFrame predicts a time at or before the epoch.
    if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    if (info->environmentBlendMode != XR_ENVIRONMENT_BLEND_MODE_OPAQUE)
      return XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED;
    if (info->layerCount > 0 && !info->layers) return XR_ERROR_VALIDATION_FAILURE;
    std::uint32_t viewCount = 0, depthCount = 0;
    for (std::uint32_t i = 0; i < info->layerCount; ++i) {
      const XrCompositionLayerBaseHeader* layer = info->layers[i];
      if (!layer || layer->type != XR_TYPE_COMPOSITION_LAYER_PROJECTION)
        return XR_ERROR_LAYER_INVALID;
      const auto* projection = reinterpret_cast<const XrCompositionLayerProjection*>(layer);
      if (projection->viewCount != 2 || !projection->views || !objectOf<Space>(projection->space))
        return XR_ERROR_VALIDATION_FAILURE;
      for (std::uint32_t v = 0; v < 2; ++v) {
        const XrSwapchainSubImage& sub = projection->views[v].subImage;
        Swapchain* swapchain = objectOf<Swapchain>(sub.swapchain);
        if (!swapchain || swapchain->session != &session) return XR_ERROR_HANDLE_INVALID;
        if (swapchain->lastReleased < 0) return XR_ERROR_LAYER_INVALID;  // nothing released
        if (sub.imageRect.offset.x < 0 || sub.imageRect.offset.y < 0 ||
            sub.imageRect.extent.width <= 0 || sub.imageRect.extent.height <= 0)
          return XR_ERROR_SWAPCHAIN_RECT_INVALID;
        if (sub.imageArrayIndex >= swapchain->images->layers()) return XR_ERROR_VALIDATION_FAILURE;
        session.lastViewSwapchain[v] = {swapchain, sub.imageArrayIndex};
        ++viewCount;
        // XR_KHR_composition_layer_depth: a depth image for the view, checked as its spec says.
        for (auto* next = static_cast<const XrBaseInStructure*>(projection->views[v].next); next;
             next = next->next) {
          if (next->type != XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR) continue;
          if (!gInstance || !gInstance->extensions.count("XR_KHR_composition_layer_depth"))
            return XR_ERROR_VALIDATION_FAILURE;  // a structure of an extension not enabled
          const auto* depth = reinterpret_cast<const XrCompositionLayerDepthInfoKHR*>(next);
          Swapchain* images = objectOf<Swapchain>(depth->subImage.swapchain);
          if (!images || images->session != &session) return XR_ERROR_HANDLE_INVALID;
          if (!images->images->depth() || images->lastReleased < 0) return XR_ERROR_LAYER_INVALID;
          if (depth->subImage.imageArrayIndex >= images->images->layers())
            return XR_ERROR_VALIDATION_FAILURE;
          if (depth->subImage.imageRect.extent.width <= 0 ||
              depth->subImage.imageRect.extent.height <= 0)
            return XR_ERROR_SWAPCHAIN_RECT_INVALID;
          if (!(depth->minDepth >= 0.0f && depth->minDepth <= 1.0f && depth->maxDepth >= 0.0f &&
                depth->maxDepth <= 1.0f && depth->minDepth < depth->maxDepth) ||
              !(depth->nearZ > 0.0f) || !(depth->farZ > 0.0f) || depth->nearZ == depth->farZ)
            return XR_ERROR_VALIDATION_FAILURE;
          ++depthCount;
        }
      }
    }
    session.begun = false;
    log("end_frame layers=" + std::to_string(info->layerCount) +
        " views=" + std::to_string(viewCount) + " depth=" + std::to_string(depthCount));
    if (!session.focusedOnce && session.state == XR_SESSION_STATE_SYNCHRONIZED) {
      session.focusedOnce = true;
      setState(session, XR_SESSION_STATE_VISIBLE);
      setState(session, XR_SESSION_STATE_FOCUSED);
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createActionSet(XrInstance handle, const XrActionSetCreateInfo* info,
                                               XrActionSet* out) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkType(info, XR_TYPE_ACTION_SET_CREATE_INFO);
    if (!out || info->actionSetName[0] == '\0') return XR_ERROR_NAME_INVALID;
    for (const auto& set : instance.actionSets)
      if (set->name == info->actionSetName) return XR_ERROR_NAME_DUPLICATED;
    auto set = std::make_unique<ActionSet>();
    set->name = info->actionSetName;
    *out = handleOf<XrActionSet>(set.get());
    instance.actionSets.insert(std::move(set));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroyActionSet(XrActionSet handle) {
  return guard([&] {
    ActionSet* set = objectOf<ActionSet>(handle);
    if (!set || !gInstance) return XR_ERROR_HANDLE_INVALID;
    for (const auto& action : set->actions) {
      gHandles.erase(action.get());
      for (auto& [profile, bindings] : gInstance->bindings)
        std::erase_if(bindings, [&](const auto& b) { return b.first == action.get(); });
    }
    gHandles.erase(set);
    std::erase_if(gInstance->actionSets, [&](const auto& s) { return s.get() == set; });
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createAction(XrActionSet handle, const XrActionCreateInfo* info,
                                            XrAction* out) {
  return guard([&] {
    ActionSet* set = objectOf<ActionSet>(handle);
    if (!set || !gInstance) return XR_ERROR_HANDLE_INVALID;
    checkType(info, XR_TYPE_ACTION_CREATE_INFO);
    if (set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    if (!out || info->actionName[0] == '\0') return XR_ERROR_NAME_INVALID;
    auto action = std::make_unique<Action>();
    action->set = set;
    action->name = info->actionName;
    action->type = info->actionType;
    for (std::uint32_t i = 0; i < info->countSubactionPaths; ++i) {
      if (handOf(pathString(*gInstance, info->subactionPaths[i])) < 0 ||
          pathString(*gInstance, info->subactionPaths[i]).find("/input") != std::string::npos)
        return XR_ERROR_PATH_UNSUPPORTED;
      action->subactions.push_back(info->subactionPaths[i]);
    }
    *out = handleOf<XrAction>(action.get());
    set->actions.push_back(std::move(action));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroyAction(XrAction handle) {
  return guard([&] {
    Action* action = objectOf<Action>(handle);
    if (!action) return XR_ERROR_HANDLE_INVALID;
    gHandles.erase(action);  // freed with its set
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL
suggestBindings(XrInstance handle, const XrInteractionProfileSuggestedBinding* suggested) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkType(suggested, XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING);
    const std::string profile = pathString(instance, suggested->interactionProfile);
    if (!knownProfile(profile)) {
      log("suggest " + profile + " unsupported");
      return XR_ERROR_PATH_UNSUPPORTED;
    }
    std::vector<std::pair<Action*, std::string>> bindings;
    for (std::uint32_t i = 0; i < suggested->countSuggestedBindings; ++i) {
      Action& action = actionOf(suggested->suggestedBindings[i].action);
      if (action.set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
      const std::string path = pathString(instance, suggested->suggestedBindings[i].binding);
      if (!bindable(profile, path, action.type)) {
        log("suggest " + profile + " unsupported " + path);
        return XR_ERROR_PATH_UNSUPPORTED;
      }
      bindings.emplace_back(&action, path);
    }
    instance.bindings[profile] = std::move(bindings);  // replaces earlier suggestions
    log("suggest " + profile + " ok");
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL attachActionSets(XrSession handle,
                                                const XrSessionActionSetsAttachInfo* info) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
    Instance& instance = *gInstance;
    if (session.attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    for (std::uint32_t i = 0; i < info->countActionSets; ++i)
      if (!objectOf<ActionSet>(info->actionSets[i])) return XR_ERROR_HANDLE_INVALID;
    session.attached = true;
    for (std::uint32_t i = 0; i < info->countActionSets; ++i)
      objectOf<ActionSet>(info->actionSets[i])->attached = true;
    instance.profile.clear();
    if (!instance.config.forcedProfile.empty()) {
      if (instance.bindings.count(instance.config.forcedProfile))
        instance.profile = instance.config.forcedProfile;
    } else {
      for (const char* profile : kProfilePreference)
        if (instance.bindings.count(profile)) {
          instance.profile = profile;
          break;
        }
    }
    if (!instance.profile.empty()) profileChanged(instance, session);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getCurrentInteractionProfile(XrSession handle, XrPath user,
                                                            XrInteractionProfileState* state) {
  return guard([&] {
    sessionOf(handle);
    checkType(state, XR_TYPE_INTERACTION_PROFILE_STATE);
    Instance& instance = *gInstance;
    if (handOf(pathString(instance, user)) < 0) return XR_ERROR_PATH_UNSUPPORTED;
    state->interactionProfile = XR_NULL_PATH;
    if (!instance.profile.empty()) {
      XrPath path = XR_NULL_PATH;
      const XrResult result =
          stringToPath(reinterpret_cast<XrInstance>(&instance), instance.profile.c_str(), &path);
      if (XR_FAILED(result)) return result;
      state->interactionProfile = path;
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL syncActions(XrSession handle, const XrActionsSyncInfo* info) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_ACTIONS_SYNC_INFO);
    Instance& instance = *gInstance;
    for (std::uint32_t i = 0; i < info->countActiveActionSets; ++i) {
      ActionSet* set = objectOf<ActionSet>(info->activeActionSets[i].actionSet);
      if (!set) return XR_ERROR_HANDLE_INVALID;
      if (!set->attached) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    }
    session.syncedFocused = session.state == XR_SESSION_STATE_FOCUSED;
    for (const auto& set : instance.actionSets)
      for (const auto& action : set->actions)
        for (int hand = 0; hand < 2; ++hand) {
          const std::optional<float> value =
              session.syncedFocused ? resolve(instance, *action, hand) : std::nullopt;
          action->previous[hand] = action->value[hand];
          action->active[hand] = value.has_value();
          action->value[hand] = value.value_or(0.0f);
          if (action->value[hand] != action->previous[hand]) action->changed[hand] = instance.time;
        }
    return session.syncedFocused ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
  });
}

// The hands an action state is read from: one (a subaction path) or both.
std::vector<int> handsFor(Action& action, XrPath subaction) {
  if (subaction == XR_NULL_PATH) return {0, 1};
  if (std::find(action.subactions.begin(), action.subactions.end(), subaction) ==
      action.subactions.end())
    fail(XR_ERROR_PATH_UNSUPPORTED);
  return {handIndex(*gInstance, subaction)};
}

template <typename State>
Action& readAction(XrSession handle, const XrActionStateGetInfo* info, State* state,
                   XrStructureType type, XrActionType actionType) {
  liveSessionOf(handle);
  checkType(info, XR_TYPE_ACTION_STATE_GET_INFO);
  checkType(state, type);
  Action& action = actionOf(info->action);
  if (action.type != actionType) fail(XR_ERROR_ACTION_TYPE_MISMATCH);
  if (!action.set->attached) fail(XR_ERROR_ACTIONSET_NOT_ATTACHED);
  return action;
}

XRAPI_ATTR XrResult XRAPI_CALL getActionStateBoolean(XrSession handle,
                                                     const XrActionStateGetInfo* info,
                                                     XrActionStateBoolean* state) {
  return guard([&] {
    Action& action =
        readAction(handle, info, state, XR_TYPE_ACTION_STATE_BOOLEAN, XR_ACTION_TYPE_BOOLEAN_INPUT);
    state->isActive = XR_FALSE;
    state->currentState = state->changedSinceLastSync = XR_FALSE;
    state->lastChangeTime = 0;
    for (int hand : handsFor(action, info->subactionPath)) {
      if (!action.active[hand]) continue;
      state->isActive = XR_TRUE;
      state->currentState |= action.value[hand] >= 0.5f;
      state->changedSinceLastSync |= action.value[hand] != action.previous[hand];
      state->lastChangeTime = std::max(state->lastChangeTime, action.changed[hand]);
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getActionStateFloat(XrSession handle,
                                                   const XrActionStateGetInfo* info,
                                                   XrActionStateFloat* state) {
  return guard([&] {
    Action& action =
        readAction(handle, info, state, XR_TYPE_ACTION_STATE_FLOAT, XR_ACTION_TYPE_FLOAT_INPUT);
    state->isActive = XR_FALSE;
    state->currentState = 0.0f;
    state->changedSinceLastSync = XR_FALSE;
    state->lastChangeTime = 0;
    for (int hand : handsFor(action, info->subactionPath)) {
      if (!action.active[hand]) continue;
      state->isActive = XR_TRUE;
      state->currentState = std::max(state->currentState, action.value[hand]);
      state->changedSinceLastSync |= action.value[hand] != action.previous[hand];
      state->lastChangeTime = std::max(state->lastChangeTime, action.changed[hand]);
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getActionStateVector2f(XrSession handle,
                                                      const XrActionStateGetInfo* info,
                                                      XrActionStateVector2f* state) {
  return guard([&] {
    readAction(handle, info, state, XR_TYPE_ACTION_STATE_VECTOR2F, XR_ACTION_TYPE_VECTOR2F_INPUT);
    state->isActive = XR_FALSE;  // the simulated user never touches a stick
    state->currentState = {0.0f, 0.0f};
    state->changedSinceLastSync = XR_FALSE;
    state->lastChangeTime = 0;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getActionStatePose(XrSession handle,
                                                  const XrActionStateGetInfo* info,
                                                  XrActionStatePose* state) {
  return guard([&] {
    Action& action =
        readAction(handle, info, state, XR_TYPE_ACTION_STATE_POSE, XR_ACTION_TYPE_POSE_INPUT);
    state->isActive = XR_FALSE;
    for (int hand : handsFor(action, info->subactionPath)) state->isActive |= action.active[hand];
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL applyHapticFeedback(XrSession handle, const XrHapticActionInfo* info,
                                                   const XrHapticBaseHeader* haptic) {
  return guard([&] {
    liveSessionOf(handle);
    checkType(info, XR_TYPE_HAPTIC_ACTION_INFO);
    checkType(haptic, XR_TYPE_HAPTIC_VIBRATION);
    Action& action = actionOf(info->action);
    if (action.type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    const auto* vibration = reinterpret_cast<const XrHapticVibration*>(haptic);
    for (int hand : handsFor(action, info->subactionPath))
      if (resolve(*gInstance, action, hand))
        log(std::string("haptic ") + (hand == 0 ? "/user/hand/left" : "/user/hand/right") +
            " amplitude=" + std::to_string(vibration->amplitude) +
            " duration=" + std::to_string(vibration->duration));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL stopHapticFeedback(XrSession handle,
                                                  const XrHapticActionInfo* info) {
  return guard([&] {
    liveSessionOf(handle);
    checkType(info, XR_TYPE_HAPTIC_ACTION_INFO);
    actionOf(info->action);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainFormats(XrSession handle, std::uint32_t capacity,
                                                         std::uint32_t* count, std::int64_t* out) {
  return guard([&] {
    Session& session = sessionOf(handle);
    fill(session.vulkan ? swapchainFormats(session.vulkan->physicalDevice)
                        : std::vector<std::int64_t>{},
         capacity, count, out);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createSwapchain(XrSession handle, const XrSwapchainCreateInfo* info,
                                               XrSwapchain* out) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_SWAPCHAIN_CREATE_INFO);
    if (!out) return XR_ERROR_VALIDATION_FAILURE;
    if (!session.vulkan) return XR_ERROR_FEATURE_UNSUPPORTED;  // headless
    const std::vector<std::int64_t> formats = swapchainFormats(session.vulkan->physicalDevice);
    if (std::find(formats.begin(), formats.end(), info->format) == formats.end())
      return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;
    if (info->width == 0 || info->height == 0 || info->width > 4096 || info->height > 4096 ||
        info->sampleCount != 1 || info->faceCount != 1 || info->arraySize == 0 ||
        info->arraySize > kMaxSwapchainLayers || info->mipCount != 1)
      return XR_ERROR_VALIDATION_FAILURE;
    VkImageUsageFlags usage = 0;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT)
      usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)
      usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_SAMPLED_BIT) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_TRANSFER_SRC_BIT)
      usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT)
      usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_UNORDERED_ACCESS_BIT)
      usage |= VK_IMAGE_USAGE_STORAGE_BIT;
    auto swapchain = std::make_unique<Swapchain>();
    swapchain->session = &session;
    swapchain->images =
        std::make_unique<SwapchainImages>(*session.vulkan, VkFormat(info->format), info->width,
                                          info->height, usage, 3, info->arraySize);
    log("swapchain " + swapchainFormatName(info->format) + " " + std::to_string(info->width) + "x" +
        std::to_string(info->height) +
        (info->arraySize > 1 ? " layers=" + std::to_string(info->arraySize) : ""));
    Swapchain* created = swapchain.release();
    session.swapchains.insert(created);
    *out = handleOf<XrSwapchain>(created);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroySwapchainEntry(XrSwapchain handle) {
  return guard([&] {
    Swapchain* swapchain = objectOf<Swapchain>(handle);
    if (!swapchain) return XR_ERROR_HANDLE_INVALID;
    destroySwapchain(swapchain);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainImages(XrSwapchain handle, std::uint32_t capacity,
                                                        std::uint32_t* count,
                                                        XrSwapchainImageBaseHeader* out) {
  return guard([&] {
    Swapchain* swapchain = objectOf<Swapchain>(handle);
    if (!swapchain) return XR_ERROR_HANDLE_INVALID;
    const auto& images = swapchain->images->images();
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = std::uint32_t(images.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < images.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    auto* vulkan = reinterpret_cast<XrSwapchainImageVulkan2KHR*>(out);
    for (std::size_t i = 0; i < images.size(); ++i) {
      if (vulkan[i].type != XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR) return XR_ERROR_VALIDATION_FAILURE;
      vulkan[i].image = images[i];
    }
    return XR_SUCCESS;
  });
}

Swapchain& swapchainOf(XrSwapchain handle) {
  Swapchain* swapchain = objectOf<Swapchain>(handle);
  if (!swapchain) fail(XR_ERROR_HANDLE_INVALID);
  liveSessionOf(reinterpret_cast<XrSession>(swapchain->session));
  return *swapchain;
}

XRAPI_ATTR XrResult XRAPI_CALL acquireSwapchainImage(XrSwapchain handle,
                                                     const XrSwapchainImageAcquireInfo*,
                                                     std::uint32_t* index) {
  return guard([&] {
    Swapchain& swapchain = swapchainOf(handle);
    if (!index) return XR_ERROR_VALIDATION_FAILURE;
    const auto size = std::uint32_t(swapchain.images->images().size());
    if (swapchain.acquired.size() >= size) return XR_ERROR_CALL_ORDER_INVALID;
    *index = swapchain.next;
    swapchain.acquired.push_back(swapchain.next);
    swapchain.next = (swapchain.next + 1) % size;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL waitSwapchainImage(XrSwapchain handle,
                                                  const XrSwapchainImageWaitInfo* info) {
  return guard([&] {
    Swapchain& swapchain = swapchainOf(handle);
    checkType(info, XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
    if (swapchain.acquired.empty() || swapchain.waited) return XR_ERROR_CALL_ORDER_INVALID;
    swapchain.waited = true;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL releaseSwapchainImage(XrSwapchain handle,
                                                     const XrSwapchainImageReleaseInfo*) {
  return guard([&] {
    Swapchain& swapchain = swapchainOf(handle);
    if (!swapchain.waited) return XR_ERROR_CALL_ORDER_INVALID;
    swapchain.waited = false;
    swapchain.lastReleased = swapchain.acquired.front();
    swapchain.acquired.pop_front();
    return XR_SUCCESS;
  });
}

// --- XR_KHR_vulkan_enable2 ---------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL getVulkanGraphicsRequirements2(
    XrInstance handle, XrSystemId system, XrGraphicsRequirementsVulkanKHR* requirements) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkSystem(system);
    checkType(requirements, XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR);
    requirements->minApiVersionSupported = XR_MAKE_VERSION(1, 0, 0);
    requirements->maxApiVersionSupported = XR_MAKE_VERSION(1, 3, 0);
    instance.requirementsCalled = true;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createVulkanInstance(XrInstance handle,
                                                    const XrVulkanInstanceCreateInfoKHR* info,
                                                    VkInstance* vulkan, VkResult* result) {
  return guard([&] {
    instanceOf(handle);
    checkType(info, XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR);
    checkSystem(info->systemId);
    if (!info->pfnGetInstanceProcAddr || !info->vulkanCreateInfo || !vulkan || !result)
      return XR_ERROR_VALIDATION_FAILURE;
    auto create = reinterpret_cast<PFN_vkCreateInstance>(
        info->pfnGetInstanceProcAddr(VK_NULL_HANDLE, "vkCreateInstance"));
    if (!create) return XR_ERROR_RUNTIME_FAILURE;
    // The simulated compositor needs nothing beyond what the application asks for.
    *result = create(info->vulkanCreateInfo, info->vulkanAllocator, vulkan);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getVulkanGraphicsDevice2(
    XrInstance handle, const XrVulkanGraphicsDeviceGetInfoKHR* info, VkPhysicalDevice* device) {
  return guard([&] {
    instanceOf(handle);
    checkType(info, XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR);
    checkSystem(info->systemId);
    if (!device || !info->vulkanInstance) return XR_ERROR_VALIDATION_FAILURE;
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(info->vulkanInstance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(info->vulkanInstance, &count, devices.data());
    if (devices.empty()) return XR_ERROR_RUNTIME_FAILURE;
    *device = devices.front();
    if (const char* wanted = std::getenv("CURVEFOLD_VK_DEVICE"))
      for (VkPhysicalDevice candidate : devices) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(candidate, &properties);
        std::string name = properties.deviceName, want = wanted;
        for (auto* s : {&name, &want})
          std::transform(s->begin(), s->end(), s->begin(),
                         [](unsigned char c) { return std::tolower(c); });
        if (name.find(want) != std::string::npos) {
          *device = candidate;
          break;
        }
      }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createVulkanDevice(XrInstance handle,
                                                  const XrVulkanDeviceCreateInfoKHR* info,
                                                  VkDevice* vulkan, VkResult* result) {
  return guard([&] {
    instanceOf(handle);
    checkType(info, XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR);
    checkSystem(info->systemId);
    if (!info->vulkanPhysicalDevice || !info->vulkanCreateInfo || !vulkan || !result)
      return XR_ERROR_VALIDATION_FAILURE;
    *result = vkCreateDevice(info->vulkanPhysicalDevice, info->vulkanCreateInfo,
                             info->vulkanAllocator, vulkan);
    return XR_SUCCESS;
  });
}

// --- Dispatch ------------------------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL getInstanceProcAddr(XrInstance instance, const char* name,
                                                   PFN_xrVoidFunction* function) {
  if (!name || !function) return XR_ERROR_VALIDATION_FAILURE;
  static const std::map<std::string, PFN_xrVoidFunction, std::less<>> table = {
#define CURVEFOLD_SIM_FN(xrName, fn) {xrName, reinterpret_cast<PFN_xrVoidFunction>(&fn)}
      CURVEFOLD_SIM_FN("xrGetInstanceProcAddr", getInstanceProcAddr),
      CURVEFOLD_SIM_FN("xrEnumerateInstanceExtensionProperties",
                       enumerateInstanceExtensionProperties),
      CURVEFOLD_SIM_FN("xrCreateInstance", createInstance),
      CURVEFOLD_SIM_FN("xrDestroyInstance", destroyInstance),
      CURVEFOLD_SIM_FN("xrGetInstanceProperties", getInstanceProperties),
      CURVEFOLD_SIM_FN("xrResultToString", resultToString),
      CURVEFOLD_SIM_FN("xrStructureTypeToString", structureTypeToString),
      CURVEFOLD_SIM_FN("xrPollEvent", pollEvent),
      CURVEFOLD_SIM_FN("xrStringToPath", stringToPath),
      CURVEFOLD_SIM_FN("xrPathToString", pathToString),
      CURVEFOLD_SIM_FN("xrGetSystem", getSystem),
      CURVEFOLD_SIM_FN("xrGetSystemProperties", getSystemProperties),
      CURVEFOLD_SIM_FN("xrEnumerateViewConfigurations", enumerateViewConfigurations),
      CURVEFOLD_SIM_FN("xrGetViewConfigurationProperties", getViewConfigurationProperties),
      CURVEFOLD_SIM_FN("xrEnumerateViewConfigurationViews", enumerateViewConfigurationViews),
      CURVEFOLD_SIM_FN("xrEnumerateEnvironmentBlendModes", enumerateEnvironmentBlendModes),
      CURVEFOLD_SIM_FN("xrCreateSession", createSession),
      CURVEFOLD_SIM_FN("xrDestroySession", destroySessionEntry),
      CURVEFOLD_SIM_FN("xrBeginSession", beginSession),
      CURVEFOLD_SIM_FN("xrEndSession", endSession),
      CURVEFOLD_SIM_FN("xrRequestExitSession", requestExitSession),
      CURVEFOLD_SIM_FN("xrEnumerateReferenceSpaces", enumerateReferenceSpaces),
      CURVEFOLD_SIM_FN("xrCreateReferenceSpace", createReferenceSpace),
      CURVEFOLD_SIM_FN("xrGetReferenceSpaceBoundsRect", getReferenceSpaceBoundsRect),
      CURVEFOLD_SIM_FN("xrCreateActionSpace", createActionSpace),
      CURVEFOLD_SIM_FN("xrLocateSpace", locateSpace),
      CURVEFOLD_SIM_FN("xrDestroySpace", destroySpace),
      CURVEFOLD_SIM_FN("xrLocateViews", locateViews),
      CURVEFOLD_SIM_FN("xrWaitFrame", waitFrame),
      CURVEFOLD_SIM_FN("xrBeginFrame", beginFrame),
      CURVEFOLD_SIM_FN("xrEndFrame", endFrame),
      CURVEFOLD_SIM_FN("xrCreateActionSet", createActionSet),
      CURVEFOLD_SIM_FN("xrDestroyActionSet", destroyActionSet),
      CURVEFOLD_SIM_FN("xrCreateAction", createAction),
      CURVEFOLD_SIM_FN("xrDestroyAction", destroyAction),
      CURVEFOLD_SIM_FN("xrSuggestInteractionProfileBindings", suggestBindings),
      CURVEFOLD_SIM_FN("xrAttachSessionActionSets", attachActionSets),
      CURVEFOLD_SIM_FN("xrGetCurrentInteractionProfile", getCurrentInteractionProfile),
      CURVEFOLD_SIM_FN("xrSyncActions", syncActions),
      CURVEFOLD_SIM_FN("xrGetActionStateBoolean", getActionStateBoolean),
      CURVEFOLD_SIM_FN("xrGetActionStateFloat", getActionStateFloat),
      CURVEFOLD_SIM_FN("xrGetActionStateVector2f", getActionStateVector2f),
      CURVEFOLD_SIM_FN("xrGetActionStatePose", getActionStatePose),
      CURVEFOLD_SIM_FN("xrApplyHapticFeedback", applyHapticFeedback),
      CURVEFOLD_SIM_FN("xrStopHapticFeedback", stopHapticFeedback),
      CURVEFOLD_SIM_FN("xrEnumerateSwapchainFormats", enumerateSwapchainFormats),
      CURVEFOLD_SIM_FN("xrCreateSwapchain", createSwapchain),
      CURVEFOLD_SIM_FN("xrDestroySwapchain", destroySwapchainEntry),
      CURVEFOLD_SIM_FN("xrEnumerateSwapchainImages", enumerateSwapchainImages),
      CURVEFOLD_SIM_FN("xrAcquireSwapchainImage", acquireSwapchainImage),
      CURVEFOLD_SIM_FN("xrWaitSwapchainImage", waitSwapchainImage),
      CURVEFOLD_SIM_FN("xrReleaseSwapchainImage", releaseSwapchainImage),
      CURVEFOLD_SIM_FN("xrGetVulkanGraphicsRequirements2KHR", getVulkanGraphicsRequirements2),
      CURVEFOLD_SIM_FN("xrCreateVulkanInstanceKHR", createVulkanInstance),
      CURVEFOLD_SIM_FN("xrGetVulkanGraphicsDevice2KHR", getVulkanGraphicsDevice2),
      CURVEFOLD_SIM_FN("xrCreateVulkanDeviceKHR", createVulkanDevice),
#undef CURVEFOLD_SIM_FN
  };
  *function = nullptr;
  const auto found = table.find(std::string_view(name));
  if (found == table.end()) return XR_ERROR_FUNCTION_UNSUPPORTED;
  // Before an instance exists only the functions that make one are reachable.
  const bool global = found->first == "xrEnumerateInstanceExtensionProperties" ||
                      found->first == "xrCreateInstance" || found->first == "xrGetInstanceProcAddr";
  if (instance == XR_NULL_HANDLE && !global) return XR_ERROR_HANDLE_INVALID;
  *function = found->second;
  return XR_SUCCESS;
}

}  // namespace
}  // namespace curvefold::simxr

extern "C" __attribute__((visibility("default"))) XrResult xrNegotiateLoaderRuntimeInterface(
    const curvefold::simxr::XrNegotiateLoaderInfo* loaderInfo,
    curvefold::simxr::XrNegotiateRuntimeRequest* request) {
  using namespace curvefold::simxr;
  if (!loaderInfo || !request || loaderInfo->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
      loaderInfo->structVersion != kLoaderInfoStructVersion ||
      loaderInfo->structSize != sizeof(XrNegotiateLoaderInfo) ||
      request->structType != XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
      request->structVersion != kRuntimeInfoStructVersion ||
      request->structSize != sizeof(XrNegotiateRuntimeRequest) ||
      loaderInfo->minInterfaceVersion > kLoaderRuntimeInterfaceVersion ||
      loaderInfo->maxInterfaceVersion < kLoaderRuntimeInterfaceVersion)
    return XR_ERROR_INITIALIZATION_FAILED;
  request->runtimeInterfaceVersion = kLoaderRuntimeInterfaceVersion;
  request->runtimeApiVersion = XR_CURRENT_API_VERSION;
  request->getInstanceProcAddr = &getInstanceProcAddr;
  return XR_SUCCESS;
}
