// An OpenXR program apart from its graphics, in the shape of hello_xr's OpenXrProgram: the
// instance, the system, the session and its full state machine (IDLE, READY, SYNCHRONIZED,
// VISIBLE, FOCUSED, STOPPING, LOSS_PENDING, EXITING), a stage reference space (local when the
// runtime has no stage), per-view swapchains and the frame loop. Rendering goes through the
// XrGraphics plugin (app/xr has the Vulkan one); with none, the session is headless
// (XR_MND_headless) and frames submit no layers.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <openxr/openxr.h>

namespace curvefold {

// One eye of a frame, as the graphics plugin draws it.
struct XrEyeView {
  std::uint32_t index = 0;  // 0 left, 1 right
  XrPosef pose{};           // in the program's base space
  XrFovf fov{};
  XrExtent2Di extent{};
  std::uint32_t colorImage = 0;             // acquired image of the view's colour swapchain
  std::optional<std::uint32_t> depthImage;  // of its depth swapchain, when it has one
  std::uint32_t arrayIndex = 0;             // its layer of an array swapchain (0 otherwise)
};

struct XrViewSwapchains {
  XrSwapchain color = XR_NULL_HANDLE;
  XrSwapchain depth = XR_NULL_HANDLE;  // null when the plugin chose none
  std::int64_t colorFormat = 0;
  std::int64_t depthFormat = 0;
  XrExtent2Di extent{};
  std::uint32_t samples = 1;
  std::uint32_t arraySize = 1;  // layers: one per view when the views share one swapchain
};

// The graphics half of the program (hello_xr's IGraphicsPlugin).
class XrGraphics {
 public:
  virtual ~XrGraphics() = default;
  virtual std::vector<std::string> instanceExtensions() const = 0;
  // Once the system is known (again after a session loss): creates the device, or checks that
  // the one made before is still the runtime's.
  virtual void initializeDevice(XrInstance instance, XrSystemId system) = 0;
  // The XrGraphicsBinding... structure chained into XrSessionCreateInfo.
  virtual const void* sessionBinding() const = 0;
  virtual std::int64_t chooseColorFormat(std::span<const std::int64_t> offered) const = 0;
  // 0: no depth swapchain.
  virtual std::int64_t chooseDepthFormat(std::span<const std::int64_t> offered,
                                         std::uint32_t samples) const = 0;
  virtual std::uint32_t chooseSampleCount(const XrViewConfigurationView& view) const = 0;
  virtual void swapchainsCreated(std::uint32_t view, const XrViewSwapchains& swapchains) = 0;
  // Before the swapchains are destroyed (the GPU must be done with them on return).
  virtual void swapchainsDestroyed() = 0;
  // Draws one eye into its acquired images; its commands are submitted on return.
  virtual void renderEye(const XrEyeView& eye) = 0;
  // How many views the plugin draws at once, into one array swapchain (layer i for view i), when
  // the views share a size: 2 for a multiview pass; 1, a swapchain per view.
  virtual std::uint32_t viewsPerSwapchain() const { return 1; }
  // Draws every view of a frame (their images acquired); by default each eye on its own.
  virtual void renderViews(std::span<const XrEyeView> eyes) {
    for (const XrEyeView& eye : eyes) renderEye(eye);
  }
  // The near and far planes the eyes are drawn with (depth 0 at near, 1 at far), for the depth
  // submitted with XR_KHR_composition_layer_depth.
  virtual float nearPlane() const = 0;
  virtual float farPlane() const = 0;
};

// Bare hands (XR_EXT_hand_tracking): used where the runtime offers them, required (`--hands`, an
// error without), or not asked for.
enum class XrHandTrackingUse { Auto, Required, Off };

struct XrProgramOptions {
  std::string applicationName = "curvefold";
  XrHandTrackingUse handTracking = XrHandTrackingUse::Auto;
};

// What pollEvents() saw.
struct XrPollResult {
  bool exitLoop = false;         // the session ended (EXITING or LOSS_PENDING) or the instance
  bool restartSession = false;   // LOSS_PENDING: destroy the session and make a new one
  bool instanceLost = false;     // the runtime is gone; only destroying the instance is left
  bool profilesChanged = false;  // an interaction profile changed
};

struct XrFrameTiming {
  XrTime displayTime = 0;
  XrDuration period = 0;
  bool shouldRender = false;
};

// The line for a machine without an OpenXR runtime.
extern const char* const kNoXrRuntime;

class XrProgram {
 public:
  // Creates the instance with the graphics plugin's extensions (XR_MND_headless when `graphics`
  // is null). Throws XrError; with no runtime, its message is kNoXrRuntime.
  XrProgram(const XrProgramOptions& options, XrGraphics* graphics);
  ~XrProgram();
  XrProgram(const XrProgram&) = delete;
  XrProgram& operator=(const XrProgram&) = delete;

  XrInstance instance() const { return instance_; }
  // Whether the depth images are submitted with the frame (the runtime has
  // XR_KHR_composition_layer_depth and the plugin made depth swapchains).
  bool submitsDepth() const {
    return depthExtension_ && !swapchains_.empty() && swapchains_[0].depth != XR_NULL_HANDLE;
  }
  // The views share one array swapchain (drawn in one multiview pass).
  bool sharesSwapchain() const { return !swapchains_.empty() && swapchains_[0].arraySize > 1; }
  const std::string& runtimeName() const { return runtimeName_; }
  // XR_EXT_hand_tracking enabled on the instance.
  bool handTrackingEnabled() const { return handTrackingExtension_; }
  // ... and the system found tracks hands.
  bool tracksHands() const { return tracksHands_; }

  // xrGetSystem for a head-mounted display: false while none is available (not connected, or
  // after a loss). The graphics plugin's device is initialised for the system found.
  bool findSystem();
  XrSystemId system() const { return system_; }
  // Creates the session, its base space (stage, else local) and the views' swapchains.
  void createSession();
  void destroySession();
  XrSession session() const { return session_; }
  XrSpace baseSpace() const { return baseSpace_; }
  XrReferenceSpaceType baseSpaceType() const { return baseSpaceType_; }

  // Drains the event queue and runs the state machine (xrBeginSession on READY, xrEndSession on
  // STOPPING).
  XrPollResult pollEvents();
  // Asks the runtime to end the session (Ctrl+C); the state machine then winds it down.
  void requestExit();

  bool running() const { return running_; }
  bool focused() const { return state_ == XR_SESSION_STATE_FOCUSED; }
  XrSessionState state() const { return state_; }
  // Every state the session went through, in order, for the log and the tests.
  const std::vector<XrSessionState>& stateHistory() const { return history_; }

  // xrWaitFrame and xrBeginFrame.
  XrFrameTiming beginFrame();
  // Locates the views, has the plugin draw each eye (when the frame should render) and ends the
  // frame with a projection layer (none when headless).
  void endFrame(const XrFrameTiming& timing);

 private:
  void createSwapchains();
  void destroySwapchains();
  void handleStateChange(const XrEventDataSessionStateChanged& event, XrPollResult& result);

  XrGraphics* graphics_;
  XrInstance instance_ = XR_NULL_HANDLE;
  std::string runtimeName_;
  XrSystemId system_ = XR_NULL_SYSTEM_ID;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace baseSpace_ = XR_NULL_HANDLE;
  XrReferenceSpaceType baseSpaceType_ = XR_REFERENCE_SPACE_TYPE_STAGE;
  XrEnvironmentBlendMode blendMode_ = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
  std::vector<XrSessionState> history_;
  bool running_ = false;
  bool exitRequested_ = false;
  bool depthExtension_ = false;  // XR_KHR_composition_layer_depth enabled
  XrHandTrackingUse handTracking_ = XrHandTrackingUse::Auto;
  bool handTrackingExtension_ = false;
  bool tracksHands_ = false;
  std::vector<XrViewConfigurationView> viewConfigs_;
  std::vector<XrViewSwapchains> swapchains_;
  std::vector<XrView> views_;
};

// Whether an OpenXR runtime is installed and has a head-mounted display now (a bare instance and
// xrGetSystem). When not, `why` says which is missing, in a few words.
bool xrHeadsetAvailable(std::string& why);

// "FOCUSED", for logs.
const char* xrSessionStateName(XrSessionState state);

}  // namespace curvefold
