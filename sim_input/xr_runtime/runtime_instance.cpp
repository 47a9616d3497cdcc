// The simulated OpenXR runtime: the instance, its extensions, paths, events and the system (the
// specification's "Instance", "Semantic Paths" and "System" chapters), and the dispatch table the
// loader reaches through xrGetInstanceProcAddr.
#include "sim_input/xr_runtime/runtime_state.hpp"

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
      CURVEFOLD_SIM_FN("xrCreateHandTrackerEXT", createHandTracker),
      CURVEFOLD_SIM_FN("xrDestroyHandTrackerEXT", destroyHandTrackerEntry),
      CURVEFOLD_SIM_FN("xrLocateHandJointsEXT", locateHandJoints),
#undef CURVEFOLD_SIM_FN
  };
  // An extension's functions exist only for an instance that enabled it.
  static const std::map<std::string, std::string, std::less<>> extensionOf = {
      {"xrCreateHandTrackerEXT", XR_EXT_HAND_TRACKING_EXTENSION_NAME},
      {"xrDestroyHandTrackerEXT", XR_EXT_HAND_TRACKING_EXTENSION_NAME},
      {"xrLocateHandJointsEXT", XR_EXT_HAND_TRACKING_EXTENSION_NAME},
  };
  *function = nullptr;
  const auto found = table.find(std::string_view(name));
  if (found == table.end()) return XR_ERROR_FUNCTION_UNSUPPORTED;
  // Before an instance exists only the functions that make one are reachable.
  const bool global = found->first == "xrEnumerateInstanceExtensionProperties" ||
                      found->first == "xrCreateInstance" || found->first == "xrGetInstanceProcAddr";
  if (instance == XR_NULL_HANDLE && !global) return XR_ERROR_HANDLE_INVALID;
  if (const auto extension = extensionOf.find(found->first); extension != extensionOf.end()) {
    Instance* object = objectOf<Instance>(instance);
    if (!object || !object->extensions.count(extension->second))
      return XR_ERROR_FUNCTION_UNSUPPORTED;
  }
  *function = found->second;
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
