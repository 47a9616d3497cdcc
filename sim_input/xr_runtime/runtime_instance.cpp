// The simulated OpenXR runtime: the instance, its extensions, paths, events and the system (the
// specification's "Instance", "Semantic Paths" and "System" chapters), and the dispatch table the
// loader reaches through xrGetInstanceProcAddr.
#include "sim_input/xr_runtime/runtime_state.hpp"

#include <string_view>

namespace curvefold::simxr {

const char* const kExtensions[] = {"XR_KHR_vulkan_enable2", "XR_MND_headless",
                                   "XR_KHR_composition_layer_depth", "XR_EXT_hand_tracking"};

// What the runtime offers: every extension, less hand tracking for a runtime set to be without
// it (CURVEFOLD_SIM_NO_HAND_TRACKING=1), read before any instance exists.
std::vector<std::string> offeredExtensions() {
  const char* noHands = std::getenv("CURVEFOLD_SIM_NO_HAND_TRACKING");
  std::vector<std::string> offered;
  for (const char* name : kExtensions)
    if (!(noHands && std::string(noHands) == "1" &&
          std::string(name) == XR_EXT_HAND_TRACKING_EXTENSION_NAME))
      offered.emplace_back(name);
  return offered;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateInstanceExtensionProperties(const char* layer,
                                                                    std::uint32_t capacity,
                                                                    std::uint32_t* count,
                                                                    XrExtensionProperties* out) {
  return guard([&] {
    if (layer) return XR_ERROR_API_LAYER_NOT_PRESENT;
    std::vector<XrExtensionProperties> all;
    for (const std::string& name : offeredExtensions()) {
      XrExtensionProperties p{XR_TYPE_EXTENSION_PROPERTIES};
      std::strncpy(p.extensionName, name.c_str(), XR_MAX_EXTENSION_NAME_SIZE - 1);
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
    const std::vector<std::string> offered = offeredExtensions();
    for (std::uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
      const std::string name = info->enabledExtensionNames[i];
      if (std::find(offered.begin(), offered.end(), name) == offered.end())
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
    instance->servingHands = instance->config.hands;
    instance->random.seed(instance->config.seed);
    if (instance->config.input)
      instance->user.emplace(instance->config.input->header.handedness);
    else
      instance->user.emplace(HandSide::Right);
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

namespace {

// The enumerants' names, from the specification's reflection lists.
#define CURVEFOLD_SIM_NAME(n, v) \
  case n:                        \
    return #n;
const char* nameOf(XrResult value) {
  switch (value) {
    XR_LIST_ENUM_XrResult(CURVEFOLD_SIM_NAME);
    default:
      return nullptr;
  }
}
const char* nameOf(XrStructureType value) {
  switch (value) {
    XR_LIST_ENUM_XrStructureType(CURVEFOLD_SIM_NAME);
    default:
      return nullptr;
  }
}
#undef CURVEFOLD_SIM_NAME

// An enumerant's name, or `unknown` and its value, into a fixed-size, always terminated buffer.
template <typename Enum>
XrResult writeName(XrInstance handle, Enum value, const char* unknown, char* buffer,
                   std::size_t size) {
  return guard([&] {
    instanceOf(handle);
    const char* name = nameOf(value);
    const std::string text = name ? name : unknown + std::to_string(int(value));
    std::strncpy(buffer, text.c_str(), size - 1);
    buffer[size - 1] = '\0';
    return XR_SUCCESS;
  });
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL resultToString(XrInstance handle, XrResult value,
                                              char buffer[XR_MAX_RESULT_STRING_SIZE]) {
  // The specification's names for a value it does not define: success or failure by its sign.
  const char* unknown = value >= 0 ? "XR_UNKNOWN_SUCCESS_" : "XR_UNKNOWN_FAILURE_";
  return writeName(handle, value, unknown, buffer, XR_MAX_RESULT_STRING_SIZE);
}

XRAPI_ATTR XrResult XRAPI_CALL structureTypeToString(XrInstance handle, XrStructureType value,
                                                     char buffer[XR_MAX_STRUCTURE_NAME_SIZE]) {
  return writeName(handle, value, "XR_UNKNOWN_STRUCTURE_TYPE_", buffer, XR_MAX_STRUCTURE_NAME_SIZE);
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
    Instance& instance = instanceOf(handle);
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
    // Hands are tracked, whether or not they are served now: the user may put the controllers
    // down at any time. The structure is only valid with the extension enabled.
    for (auto* next = static_cast<XrBaseOutStructure*>(properties->next); next; next = next->next)
      if (next->type == XR_TYPE_SYSTEM_HAND_TRACKING_PROPERTIES_EXT &&
          instance.extensions.count(XR_EXT_HAND_TRACKING_EXTENSION_NAME))
        reinterpret_cast<XrSystemHandTrackingPropertiesEXT*>(next)->supportsHandTracking = XR_TRUE;
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

// --- Dispatch ------------------------------------------------------------------------------------

namespace {

// An entry point, and who may fetch it: also without an instance (the functions that make one),
// and only for an instance that enabled `extension` (when set).
struct NamedFunction {
  std::string_view name;
  PFN_xrVoidFunction function;
  bool global = false;
  const char* extension = nullptr;
};

// An entry point as the loader takes it. The table is const, not constexpr: a cast between
// function pointer types is not a constant expression.
template <typename Function>
PFN_xrVoidFunction erased(Function* function) {
  return reinterpret_cast<PFN_xrVoidFunction>(function);
}

constexpr const char* kHandTracking = XR_EXT_HAND_TRACKING_EXTENSION_NAME;
constexpr const char* kVulkan = XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME;

const NamedFunction kFunctions[] = {
    {"xrGetInstanceProcAddr", erased(getInstanceProcAddr), true},
    {"xrEnumerateInstanceExtensionProperties", erased(enumerateInstanceExtensionProperties), true},
    {"xrCreateInstance", erased(createInstance), true},
    {"xrDestroyInstance", erased(destroyInstance)},
    {"xrGetInstanceProperties", erased(getInstanceProperties)},
    {"xrResultToString", erased(resultToString)},
    {"xrStructureTypeToString", erased(structureTypeToString)},
    {"xrPollEvent", erased(pollEvent)},
    {"xrStringToPath", erased(stringToPath)},
    {"xrPathToString", erased(pathToString)},
    {"xrGetSystem", erased(getSystem)},
    {"xrGetSystemProperties", erased(getSystemProperties)},
    {"xrEnumerateViewConfigurations", erased(enumerateViewConfigurations)},
    {"xrGetViewConfigurationProperties", erased(getViewConfigurationProperties)},
    {"xrEnumerateViewConfigurationViews", erased(enumerateViewConfigurationViews)},
    {"xrEnumerateEnvironmentBlendModes", erased(enumerateEnvironmentBlendModes)},
    {"xrCreateSession", erased(createSession)},
    {"xrDestroySession", erased(destroySessionEntry)},
    {"xrBeginSession", erased(beginSession)},
    {"xrEndSession", erased(endSession)},
    {"xrRequestExitSession", erased(requestExitSession)},
    {"xrEnumerateReferenceSpaces", erased(enumerateReferenceSpaces)},
    {"xrCreateReferenceSpace", erased(createReferenceSpace)},
    {"xrGetReferenceSpaceBoundsRect", erased(getReferenceSpaceBoundsRect)},
    {"xrCreateActionSpace", erased(createActionSpace)},
    {"xrLocateSpace", erased(locateSpace)},
    {"xrDestroySpace", erased(destroySpace)},
    {"xrLocateViews", erased(locateViews)},
    {"xrWaitFrame", erased(waitFrame)},
    {"xrBeginFrame", erased(beginFrame)},
    {"xrEndFrame", erased(endFrame)},
    {"xrCreateActionSet", erased(createActionSet)},
    {"xrDestroyActionSet", erased(destroyActionSet)},
    {"xrCreateAction", erased(createAction)},
    {"xrDestroyAction", erased(destroyAction)},
    {"xrSuggestInteractionProfileBindings", erased(suggestBindings)},
    {"xrAttachSessionActionSets", erased(attachActionSets)},
    {"xrGetCurrentInteractionProfile", erased(getCurrentInteractionProfile)},
    {"xrSyncActions", erased(syncActions)},
    {"xrGetActionStateBoolean", erased(getActionStateBoolean)},
    {"xrGetActionStateFloat", erased(getActionStateFloat)},
    {"xrGetActionStateVector2f", erased(getActionStateVector2f)},
    {"xrGetActionStatePose", erased(getActionStatePose)},
    {"xrApplyHapticFeedback", erased(applyHapticFeedback)},
    {"xrStopHapticFeedback", erased(stopHapticFeedback)},
    {"xrEnumerateSwapchainFormats", erased(enumerateSwapchainFormats)},
    {"xrCreateSwapchain", erased(createSwapchain)},
    {"xrDestroySwapchain", erased(destroySwapchainEntry)},
    {"xrEnumerateSwapchainImages", erased(enumerateSwapchainImages)},
    {"xrAcquireSwapchainImage", erased(acquireSwapchainImage)},
    {"xrWaitSwapchainImage", erased(waitSwapchainImage)},
    {"xrReleaseSwapchainImage", erased(releaseSwapchainImage)},
    {"xrGetVulkanGraphicsRequirements2KHR", erased(getVulkanGraphicsRequirements2), false, kVulkan},
    {"xrCreateVulkanInstanceKHR", erased(createVulkanInstance), false, kVulkan},
    {"xrGetVulkanGraphicsDevice2KHR", erased(getVulkanGraphicsDevice2), false, kVulkan},
    {"xrCreateVulkanDeviceKHR", erased(createVulkanDevice), false, kVulkan},
    {"xrCreateHandTrackerEXT", erased(createHandTracker), false, kHandTracking},
    {"xrDestroyHandTrackerEXT", erased(destroyHandTrackerEntry), false, kHandTracking},
    {"xrLocateHandJointsEXT", erased(locateHandJoints), false, kHandTracking},
};

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL getInstanceProcAddr(XrInstance instance, const char* name,
                                                   PFN_xrVoidFunction* function) {
  if (!name || !function) return XR_ERROR_VALIDATION_FAILURE;
  *function = nullptr;
  const auto found = std::find_if(std::begin(kFunctions), std::end(kFunctions),
                                  [&](const NamedFunction& f) { return f.name == name; });
  if (found == std::end(kFunctions)) return XR_ERROR_FUNCTION_UNSUPPORTED;
  if (instance == XR_NULL_HANDLE && !found->global) return XR_ERROR_HANDLE_INVALID;
  if (found->extension) {
    const Instance* object = objectOf<Instance>(instance);
    if (!object || !object->extensions.count(found->extension))
      return XR_ERROR_FUNCTION_UNSUPPORTED;
  }
  *function = found->function;
  return XR_SUCCESS;
}

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
