#include "interaction/xr/xr_program.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "interaction/xr/xr_check.hpp"
#include "interaction/xr/xr_hand_tracking.hpp"

namespace curvefold {

const char* const kNoXrRuntime =
    "no OpenXR runtime: install one (Monado, SteamVR, ...) or point XR_RUNTIME_JSON at a "
    "runtime's manifest";

namespace {

// What a runtime writes to standard error while it starts, held: a refusal is then said in one
// line with the runtime's reason (it printed its line and curvefold another), and what a runtime
// that starts prints is passed on unchanged.
class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    saved_ = file_ ? ::dup(STDERR_FILENO) : -1;
    if (saved_ >= 0 && ::dup2(::fileno(file_), STDERR_FILENO) < 0) {
      ::close(saved_);
      saved_ = -1;
    }
  }
  ~StderrCapture() {
    finish();
    if (file_) std::fclose(file_);
  }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  // Standard error back as it was; what was written meanwhile (its first 64 KiB).
  std::string finish() {
    if (saved_ < 0) return "";
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
    std::string text;
    std::rewind(file_);
    char buffer[4096];
    for (std::size_t n;
         text.size() < (64u << 10) && (n = std::fread(buffer, 1, sizeof buffer, file_)) > 0;)
      text.append(buffer, n);
    return text;
  }

 private:
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

// The last line with something on it, without its end of line.
std::string lastLine(const std::string& text) {
  const std::size_t end = text.find_last_not_of(" \t\r\n");
  if (end == std::string::npos) return "";
  const std::size_t newline = text.rfind('\n', end);
  const std::size_t start = newline == std::string::npos ? 0 : newline + 1;
  return text.substr(start, end + 1 - start);
}

constexpr XrViewConfigurationType kViewConfig = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;

std::vector<std::string> availableExtensions() {
  std::uint32_t count = 0;
  CHECK_XR(xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr));
  std::vector<XrExtensionProperties> properties(count, {XR_TYPE_EXTENSION_PROPERTIES});
  CHECK_XR(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, properties.data()));
  std::vector<std::string> names;
  for (const XrExtensionProperties& p : properties) names.emplace_back(p.extensionName);
  return names;
}

bool isNoRuntime(XrResult result) {
  return result == XR_ERROR_RUNTIME_UNAVAILABLE || result == XR_ERROR_RUNTIME_FAILURE ||
         result == XR_ERROR_INSTANCE_LOST || result == XR_ERROR_INITIALIZATION_FAILED;
}

}  // namespace

bool xrHeadsetAvailable(std::string& why) {
  setenv("XR_LOADER_DEBUG", "none", 0);
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strncpy(info.applicationInfo.applicationName, "curvefold probe",
               XR_MAX_APPLICATION_NAME_SIZE - 1);
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  XrInstance instance = XR_NULL_HANDLE;
  if (XR_FAILED(xrCreateInstance(&info, &instance))) {
    why = "no OpenXR runtime; XR_RUNTIME_JSON names one";
    return false;
  }
  XrSystemGetInfo system{XR_TYPE_SYSTEM_GET_INFO};
  system.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId id = XR_NULL_SYSTEM_ID;
  const bool found = XR_SUCCEEDED(xrGetSystem(instance, &system, &id));
  xrDestroyInstance(instance);
  if (!found) why = "the OpenXR runtime has no headset connected";
  return found;
}

const char* xrSessionStateName(XrSessionState state) {
  switch (state) {
    case XR_SESSION_STATE_IDLE:
      return "IDLE";
    case XR_SESSION_STATE_READY:
      return "READY";
    case XR_SESSION_STATE_SYNCHRONIZED:
      return "SYNCHRONIZED";
    case XR_SESSION_STATE_VISIBLE:
      return "VISIBLE";
    case XR_SESSION_STATE_FOCUSED:
      return "FOCUSED";
    case XR_SESSION_STATE_STOPPING:
      return "STOPPING";
    case XR_SESSION_STATE_LOSS_PENDING:
      return "LOSS_PENDING";
    case XR_SESSION_STATE_EXITING:
      return "EXITING";
    default:
      return "UNKNOWN";
  }
}

XrProgram::XrProgram(const XrProgramOptions& options, XrGraphics* graphics)
    : graphics_(graphics), handTracking_(options.handTracking) {
  // The loader prints its own errors to stderr; ours say what to do in one line.
  setenv("XR_LOADER_DEBUG", "none", 0);
  std::vector<std::string> offered;
  try {
    offered = availableExtensions();
  } catch (const XrError& e) {
    if (isNoRuntime(e.result())) throw XrError(kNoXrRuntime, e.result());
    throw;
  }
  std::vector<std::string> wanted =
      graphics_ ? graphics_->instanceExtensions() : std::vector<std::string>{"XR_MND_headless"};
  std::vector<const char*> names;
  for (const std::string& name : wanted) {
    if (std::find(offered.begin(), offered.end(), name) == offered.end()) {
      if (!graphics_)
        throw XrMissingFeature("the OpenXR runtime lacks " + name, XR_ERROR_EXTENSION_NOT_PRESENT,
                               XrFeature::Headless);
      throw XrError("the OpenXR runtime lacks " + name + " (needed to render with Vulkan)",
                    XR_ERROR_EXTENSION_NOT_PRESENT);
    }
    names.push_back(name.c_str());
  }
  // Depth for the compositor's reprojection, where the runtime takes it.
  const char* const depthLayer = XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME;
  if (graphics_ && std::find(offered.begin(), offered.end(), depthLayer) != offered.end()) {
    names.push_back(depthLayer);
    depthExtension_ = true;
  }
  const char* const hands = XR_EXT_HAND_TRACKING_EXTENSION_NAME;
  if (handTracking_ != XrHandTrackingUse::Off) {
    if (std::find(offered.begin(), offered.end(), hands) != offered.end()) {
      names.push_back(hands);
      handTrackingExtension_ = true;
    } else if (handTracking_ == XrHandTrackingUse::Required) {
      throw XrMissingFeature(std::string("the OpenXR runtime lacks ") + hands,
                             XR_ERROR_EXTENSION_NOT_PRESENT, XrFeature::HandTracking);
    }
  }

  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strncpy(info.applicationInfo.applicationName, options.applicationName.c_str(),
               XR_MAX_APPLICATION_NAME_SIZE - 1);
  std::strncpy(info.applicationInfo.engineName, "curvefold", XR_MAX_ENGINE_NAME_SIZE - 1);
  info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  info.enabledExtensionCount = static_cast<std::uint32_t>(names.size());
  info.enabledExtensionNames = names.data();
  // The runtime was found (it listed its extensions): a refusal now is the runtime's, not a
  // missing one, and what to do is in the line it printed, which the one error line quotes.
  StderrCapture capture;
  const XrResult created = xrCreateInstance(&info, &instance_);
  const std::string printed = capture.finish();
  if (isNoRuntime(created)) {
    const std::string reason = lastLine(printed);
    throw XrError("the OpenXR runtime was found but refused to start (" + xrResultName(created) +
                      (reason.empty() ? "), saying nothing of why" : "): " + reason),
                  created);
  }
  if (!printed.empty()) std::fwrite(printed.data(), 1, printed.size(), stderr);
  CHECK_XR(created);

  XrInstanceProperties properties{XR_TYPE_INSTANCE_PROPERTIES};
  if (XR_SUCCEEDED(xrGetInstanceProperties(instance_, &properties)))
    runtimeName_ = properties.runtimeName;
}

XrProgram::~XrProgram() {
  destroySession();
  if (instance_ != XR_NULL_HANDLE) xrDestroyInstance(instance_);
}

bool XrProgram::findSystem() {
  XrSystemGetInfo info{XR_TYPE_SYSTEM_GET_INFO};
  info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  const XrResult result = xrGetSystem(instance_, &info, &system_);
  if (result == XR_ERROR_FORM_FACTOR_UNAVAILABLE) return false;
  CHECK_XR(result);

  std::uint32_t count = 0;
  CHECK_XR(xrEnumerateViewConfigurationViews(instance_, system_, kViewConfig, 0, &count, nullptr));
  viewConfigs_.assign(count, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
  CHECK_XR(xrEnumerateViewConfigurationViews(instance_, system_, kViewConfig, count, &count,
                                             viewConfigs_.data()));
  CHECK_XR(xrEnumerateEnvironmentBlendModes(instance_, system_, kViewConfig, 0, &count, nullptr));
  std::vector<XrEnvironmentBlendMode> modes(count);
  CHECK_XR(xrEnumerateEnvironmentBlendModes(instance_, system_, kViewConfig, count, &count,
                                            modes.data()));
  if (modes.empty())
    throw XrError("the OpenXR runtime offers no blend mode", XR_ERROR_RUNTIME_FAILURE);
  blendMode_ = modes.front();  // the runtime's preference
  tracksHands_ = handTrackingExtension_ && xrSystemTracksHands(instance_, system_);
  if (handTracking_ == XrHandTrackingUse::Required && !tracksHands_)
    throw XrMissingFeature("the headset does not track hands", XR_ERROR_FEATURE_UNSUPPORTED,
                           XrFeature::HandTracking);
  if (graphics_) graphics_->initializeDevice(instance_, system_);
  return true;
}

void XrProgram::createSession() {
  XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
  info.next = graphics_ ? graphics_->sessionBinding() : nullptr;
  info.systemId = system_;
  CHECK_XR(xrCreateSession(instance_, &info, &session_));
  state_ = XR_SESSION_STATE_UNKNOWN;
  running_ = false;
  exitRequested_ = false;

  std::uint32_t count = 0;
  CHECK_XR(xrEnumerateReferenceSpaces(session_, 0, &count, nullptr));
  std::vector<XrReferenceSpaceType> spaces(count);
  CHECK_XR(xrEnumerateReferenceSpaces(session_, count, &count, spaces.data()));
  // The stage's floor origin suits a sheet held at table height; local is always there.
  baseSpaceType_ =
      std::find(spaces.begin(), spaces.end(), XR_REFERENCE_SPACE_TYPE_STAGE) != spaces.end()
          ? XR_REFERENCE_SPACE_TYPE_STAGE
          : XR_REFERENCE_SPACE_TYPE_LOCAL;
  XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  space.referenceSpaceType = baseSpaceType_;
  space.poseInReferenceSpace.orientation.w = 1.0f;
  CHECK_XR(xrCreateReferenceSpace(session_, &space, &baseSpace_));
  if (graphics_) createSwapchains();
}

void XrProgram::createSwapchains() {
  std::uint32_t count = 0;
  CHECK_XR(xrEnumerateSwapchainFormats(session_, 0, &count, nullptr));
  std::vector<std::int64_t> formats(count);
  CHECK_XR(xrEnumerateSwapchainFormats(session_, count, &count, formats.data()));
  // One array swapchain for all views when the plugin draws them at once and they share a size.
  const std::uint32_t viewCount = std::uint32_t(viewConfigs_.size());
  bool shared = viewCount > 1 && graphics_->viewsPerSwapchain() >= viewCount;
  for (const XrViewConfigurationView& config : viewConfigs_)
    shared =
        shared && config.recommendedImageRectWidth == viewConfigs_[0].recommendedImageRectWidth &&
        config.recommendedImageRectHeight == viewConfigs_[0].recommendedImageRectHeight &&
        config.recommendedSwapchainSampleCount == viewConfigs_[0].recommendedSwapchainSampleCount;
  for (std::uint32_t i = 0; i < (shared ? 1u : viewCount); ++i) {
    const XrViewConfigurationView& config = viewConfigs_[i];
    XrViewSwapchains chains;
    chains.arraySize = shared ? viewCount : 1;
    chains.samples = graphics_->chooseSampleCount(config);
    chains.extent = {std::int32_t(config.recommendedImageRectWidth),
                     std::int32_t(config.recommendedImageRectHeight)};
    chains.colorFormat = graphics_->chooseColorFormat(formats);
    chains.depthFormat = graphics_->chooseDepthFormat(formats, chains.samples);
    XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    info.arraySize = chains.arraySize;
    info.faceCount = 1;
    info.mipCount = 1;
    info.sampleCount = 1;  // MSAA, when used, resolves into these
    info.width = config.recommendedImageRectWidth;
    info.height = config.recommendedImageRectHeight;
    info.format = chains.colorFormat;
    info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
    CHECK_XR(xrCreateSwapchain(session_, &info, &chains.color));
    if (chains.depthFormat != 0) {
      info.format = chains.depthFormat;
      info.usageFlags = XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
      CHECK_XR(xrCreateSwapchain(session_, &info, &chains.depth));
    }
    swapchains_.push_back(chains);
    graphics_->swapchainsCreated(i, chains);
  }
  views_.assign(viewConfigs_.size(), {XR_TYPE_VIEW});
}

void XrProgram::destroySwapchains() {
  if (swapchains_.empty()) return;
  if (graphics_) graphics_->swapchainsDestroyed();
  for (const XrViewSwapchains& chains : swapchains_) {
    xrDestroySwapchain(chains.color);
    if (chains.depth != XR_NULL_HANDLE) xrDestroySwapchain(chains.depth);
  }
  swapchains_.clear();
}

void XrProgram::destroySession() {
  if (session_ == XR_NULL_HANDLE) return;
  destroySwapchains();
  if (baseSpace_ != XR_NULL_HANDLE) xrDestroySpace(baseSpace_);
  baseSpace_ = XR_NULL_HANDLE;
  xrDestroySession(session_);
  session_ = XR_NULL_HANDLE;
  running_ = false;
}

void XrProgram::handleStateChange(const XrEventDataSessionStateChanged& event,
                                  XrPollResult& result) {
  if (event.session != XR_NULL_HANDLE && event.session != session_) return;
  state_ = event.state;
  history_.push_back(state_);
  switch (state_) {
    case XR_SESSION_STATE_READY: {
      XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
      begin.primaryViewConfigurationType = kViewConfig;
      CHECK_XR(xrBeginSession(session_, &begin));
      running_ = true;
      break;
    }
    case XR_SESSION_STATE_STOPPING:
      running_ = false;
      CHECK_XR(xrEndSession(session_));
      break;
    case XR_SESSION_STATE_EXITING:
      result.exitLoop = true;
      break;
    case XR_SESSION_STATE_LOSS_PENDING:
      // The runtime may come back (a headset reconnected): make a new session then.
      running_ = false;
      result.exitLoop = true;
      result.restartSession = true;
      break;
    default:
      break;
  }
}

XrPollResult XrProgram::pollEvents() {
  XrPollResult result;
  for (;;) {
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
    const XrResult polled = CHECK_XR(xrPollEvent(instance_, &event));
    if (polled == XR_EVENT_UNAVAILABLE) break;
    switch (event.type) {
      case XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED:
        handleStateChange(reinterpret_cast<const XrEventDataSessionStateChanged&>(event), result);
        break;
      case XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING:
        running_ = false;
        result.exitLoop = true;
        result.instanceLost = true;
        return result;
      case XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED:
        result.profilesChanged = true;
        break;
      default:
        break;  // events lost, reference space changes: nothing to do
    }
  }
  return result;
}

void XrProgram::requestExit() {
  if (session_ == XR_NULL_HANDLE || exitRequested_) return;
  exitRequested_ = true;
  if (running_) CHECK_XR(xrRequestExitSession(session_));
}

XrFrameTiming XrProgram::beginFrame() {
  XrFrameWaitInfo waitInfo{XR_TYPE_FRAME_WAIT_INFO};
  XrFrameState frameState{XR_TYPE_FRAME_STATE};
  CHECK_XR(xrWaitFrame(session_, &waitInfo, &frameState));
  XrFrameBeginInfo beginInfo{XR_TYPE_FRAME_BEGIN_INFO};
  CHECK_XR(xrBeginFrame(session_, &beginInfo));
  return {frameState.predictedDisplayTime, frameState.predictedDisplayPeriod,
          frameState.shouldRender == XR_TRUE};
}

void XrProgram::endFrame(const XrFrameTiming& timing) {
  std::vector<XrCompositionLayerProjectionView> projectionViews;
  std::vector<XrCompositionLayerDepthInfoKHR> depthInfos;
  XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  const XrCompositionLayerBaseHeader* layers[] = {
      reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
  bool submitLayer = false;
  if (timing.shouldRender && graphics_ && !swapchains_.empty()) {
    XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO};
    locate.viewConfigurationType = kViewConfig;
    locate.displayTime = timing.displayTime;
    locate.space = baseSpace_;
    XrViewState viewState{XR_TYPE_VIEW_STATE};
    std::uint32_t count = 0;
    CHECK_XR(xrLocateViews(session_, &locate, &viewState, std::uint32_t(views_.size()), &count,
                           views_.data()));
    // No head pose, no picture: a frame with no layers keeps the session going.
    const std::uint32_t viewCount = std::uint32_t(viewConfigs_.size());
    submitLayer = (viewState.viewStateFlags & XR_VIEW_STATE_POSITION_VALID_BIT) &&
                  (viewState.viewStateFlags & XR_VIEW_STATE_ORIENTATION_VALID_BIT) &&
                  count == viewCount;
    if (submitLayer) {
      // Each swapchain's image once (a shared array swapchain serves every view), the views drawn
      // (at once, when the plugin can), then the images released.
      std::vector<std::uint32_t> colorImages(swapchains_.size());
      std::vector<std::optional<std::uint32_t>> depthImages(swapchains_.size());
      XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
      XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
      wait.timeout = XR_INFINITE_DURATION;
      for (std::size_t k = 0; k < swapchains_.size(); ++k) {
        const XrViewSwapchains& chains = swapchains_[k];
        CHECK_XR(xrAcquireSwapchainImage(chains.color, &acquire, &colorImages[k]));
        CHECK_XR(xrWaitSwapchainImage(chains.color, &wait));
        if (chains.depth != XR_NULL_HANDLE) {
          std::uint32_t depthImage = 0;
          CHECK_XR(xrAcquireSwapchainImage(chains.depth, &acquire, &depthImage));
          CHECK_XR(xrWaitSwapchainImage(chains.depth, &wait));
          depthImages[k] = depthImage;
        }
      }
      const bool shared = sharesSwapchain();
      std::vector<XrEyeView> eyes(count);
      for (std::uint32_t i = 0; i < count; ++i) {
        const std::size_t k = shared ? 0 : i;
        XrEyeView& eye = eyes[i];
        eye.index = i;
        eye.pose = views_[i].pose;
        eye.fov = views_[i].fov;
        eye.extent = swapchains_[k].extent;
        eye.colorImage = colorImages[k];
        eye.depthImage = depthImages[k];
        eye.arrayIndex = shared ? i : 0;
      }
      graphics_->renderViews(eyes);
      for (const XrViewSwapchains& chains : swapchains_) {
        XrSwapchainImageReleaseInfo release{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
        CHECK_XR(xrReleaseSwapchainImage(chains.color, &release));
        if (chains.depth != XR_NULL_HANDLE)
          CHECK_XR(xrReleaseSwapchainImage(chains.depth, &release));
      }
      projectionViews.resize(count);
      depthInfos.resize(count);
      for (std::uint32_t i = 0; i < count; ++i) {
        const XrViewSwapchains& chains = swapchains_[shared ? 0 : i];
        XrCompositionLayerProjectionView& view = projectionViews[i];
        view = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
        view.pose = views_[i].pose;
        view.fov = views_[i].fov;
        view.subImage.swapchain = chains.color;
        view.subImage.imageRect = {{0, 0}, chains.extent};
        view.subImage.imageArrayIndex = eyes[i].arrayIndex;
        if (depthExtension_ && chains.depth != XR_NULL_HANDLE) {
          XrCompositionLayerDepthInfoKHR& depth = depthInfos[i];
          depth = {XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR};
          depth.subImage.swapchain = chains.depth;
          depth.subImage.imageRect = {{0, 0}, chains.extent};
          depth.subImage.imageArrayIndex = eyes[i].arrayIndex;
          depth.minDepth = 0.0f;
          depth.maxDepth = 1.0f;
          depth.nearZ = graphics_->nearPlane();
          depth.farZ = graphics_->farPlane();
          view.next = &depth;
        }
      }
      layer.space = baseSpace_;
      layer.viewCount = count;
      layer.views = projectionViews.data();
    }
  }
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = timing.displayTime;
  end.environmentBlendMode = blendMode_;
  end.layerCount = submitLayer ? 1 : 0;
  end.layers = submitLayer ? layers : nullptr;
  CHECK_XR(xrEndFrame(session_, &end));
}

}  // namespace curvefold
