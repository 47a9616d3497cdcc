// `curvefold xr`: folding with tracked controllers (docs/design.md 5-7). The XR program (instance,
// session state machine, frame loop), the XR input source feeding the one InteractionCore, the
// recorder and the autosave, and the Vulkan plugin drawing each eye. A lost session (LOSS_PENDING)
// is destroyed and made again when the runtime has a headset again; the fold session lives
// outside it, so no committed fold is lost. Ctrl+C asks the runtime to end the session and the
// state machine winds it down like any other exit.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "app/desktop/interaction_scene.hpp"
#include "app/session/document.hpp"
#include "app/session/session_outputs.hpp"
#include "app/studio/studio_panel.hpp"
#include "app/xr/xr_vulkan_graphics.hpp"
#include "engine/render/scene.hpp"
#include "interaction/input_frame.hpp"
#include "interaction/xr/xr_program.hpp"

namespace curvefold {
class XrInput;
class SessionSheetTracker;
}  // namespace curvefold

namespace curvefold::studio {
class HeadsetStudio;
}  // namespace curvefold::studio

namespace curvefold::xr {

class PanelTexture;

struct XrAppOptions {
  std::string input;      // design file, surface name, recording (its surface) or empty
  std::string record;     // recording of this session's input frames (*.jsonl)
  std::string autosave;   // design written after every committed fold and at the end
  std::string exportDir;  // where the panel's exports go (default: beside the design)
  std::string target;     // a target shape (OBJ) to fold toward, shown and suggested in the panel
  bool leftHanded = false;
  bool hands = false;     // bare hands only (XR_EXT_hand_tracking), controllers ignored
  bool headless = false;  // XR_MND_headless: input only, nothing drawn
  bool validation = false;
  XrMultiview multiview = XrMultiview::Auto;  // both eyes in one pass (xr_vulkan_graphics.hpp)
};

struct XrAppSummary {
  std::string runtime;
  std::size_t framesProcessed = 0;  // focused frames fed to the interaction core
  std::size_t handFrames = 0;       // of those, frames a bare hand drove a role in
  std::size_t framesRendered = 0;
  std::size_t sessions = 0;  // more than one after a session loss
  std::size_t folds = 0;
  std::vector<std::string> states;      // every session state, in order
  std::array<std::string, 2> profiles;  // the last interaction profile of each hand
  bool instanceLost = false;
  bool interrupted = false;  // ended by requestExit (Ctrl+C)
  std::string autosave;      // the last design's (a new sheet from the panel starts another)
  std::vector<std::string> problems;  // panel actions that failed, and files not kept
};

class XrApp {
 public:
  explicit XrApp(const XrAppOptions& options);
  ~XrApp();
  XrApp(const XrApp&) = delete;
  XrApp& operator=(const XrApp&) = delete;

  // Runs until the runtime ends the session (or the instance is lost). `interrupt` is polled
  // every frame; once set, the app asks the runtime to exit.
  XrAppSummary run(const std::atomic<bool>& interrupt);

  // One frame of a running session: wait, input, fold, record, draw, end. For the benchmark.
  void frame();
  // The session's state machine, once (events); false when the loop should stop.
  bool pollEvents();
  bool sessionRunning() const;
  bool startSession();  // finds the system and creates the session; false without a headset

  const session::Document& document() const { return doc_; }
  const studio::HeadsetStudio& studio() const { return *studio_; }
  const std::string& runtimeName() const { return summary_.runtime; }

 private:
  XrAppSummary runSessions(const std::atomic<bool>& interrupt);
  void processInput(XrTime displayTime);
  void startRecording();
  const Scene& eyeScene(std::span<const Camera> cameras);
  void makeStudio(const Pose& sheetFrame);
  void addStudio(Scene& scene);
  void buildScene();

  XrAppOptions options_;
  session::Document doc_;
  std::unique_ptr<XrVulkanGraphics> graphics_;
  std::unique_ptr<XrProgram> program_;
  std::unique_ptr<XrInput> input_;
  std::unique_ptr<desktop::InteractionSheetTracker> tracker_;
  std::string autosave_;
  std::string startName_;  // what the autosave and exports are named after without an input
  RecordingHeader recordingHeader_;  // its rate is set from the runtime's frame period
  // After doc_: finishes (saves) before doc_ goes.
  std::unique_ptr<session::SessionOutputs> outputs_;
  std::unique_ptr<studio::HeadsetStudio> studio_;  // after doc_, which it edits
  std::unique_ptr<PanelTexture> panelTexture_;     // after studio_, whose ImGui context it uses
  std::uint64_t texturedRenderer_ = 0;             // the renderer (generation) given its texture
  std::chrono::steady_clock::time_point lastFrame_{};
  InputFrame lastInput_;
  bool haveFirstTime_ = false;
  XrTime firstTime_ = 0;
  XrDuration period_ = 0;  // the runtime's frame period, for the recording's rate
  double lastSeconds_ = 0.0;
  Scene scene_;
  Ground ground_;
  desktop::CreasePatternCache panelCache_;
  studio::StudioStats stats_;
  bool restart_ = false;
  XrAppSummary summary_;
  // The live simulation's GPU solver on graphics_'s device (none: no device, or no compute).
  const VulkanContext* gpuContext_ = nullptr;
  LiveSolverFactory gpuSolver_;
};

}  // namespace curvefold::xr
