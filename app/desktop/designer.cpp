// The desktop designer window (docs/design.md 5 and 7; the command is app/cli/design_command.cpp).
// A GLFW window with a SwapchainTarget, the shared SceneRenderer, an ImGui panel, and DesktopInput
// feeding the one InteractionCore; recorded with --record, autosaved after every committed fold.
// GLFW declares glfwCreateWindowSurface only with Vulkan's header.
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <time.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include "app/desktop/designer.hpp"
#include "app/desktop/desktop_input.hpp"
#include "app/desktop/gpu_live_solver.hpp"
#include "app/desktop/interaction_scene.hpp"
#include "app/desktop/redraw_pacer.hpp"
#include "app/desktop/thread_cpu.hpp"
#include "app/session/document.hpp"
#include "app/session/recent_designs.hpp"
#include "app/session/session_outputs.hpp"
#include "app/studio/studio_panel.hpp"
#include "app/studio/studio_target.hpp"
#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/gltf_writer.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/image.hpp"
#include "engine/render/offscreen_target.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/render/sheet_tracker.hpp"
#include "engine/render/swapchain_target.hpp"
#include "engine/render/vulkan_objects.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "engine/text/environment_choice.hpp"
#include "sim_input/player.hpp"

namespace curvefold::desktop {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kNoDisplay = "no display for the designer window";
constexpr const char* kDefaultSurface = "square";
constexpr const char* kHelp =
    "Left drag: fold (simulating: pull the paper; wheel: depth). Right: orbit, middle: pan, "
    "wheel: zoom. Esc "
    "cancels, Ctrl+Z / Ctrl+Shift+Z undo/redo, Ctrl+Q quits. With a target: S "
    "suggests a fold, T takes it, N offers another.";

// GLFW's window, created and destroyed with glfwInit/glfwTerminate around it.
struct Glfw {
  Glfw() {
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr)
      throw NoDisplayError(kNoDisplay);
    glfwSetErrorCallback([](int, const char*) {});  // glfwInit's failure is reported below
    if (!glfwInit()) throw NoDisplayError(kNoDisplay);
    if (!glfwVulkanSupported()) {
      glfwTerminate();
      throw std::runtime_error("no Vulkan loader usable with the window system");
    }
  }
  // Delegating: a window that cannot be made still terminates GLFW (the destructor runs).
  Glfw(unsigned width, unsigned height) : Glfw() {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window = glfwCreateWindow(int(width), int(height), "curvefold", nullptr, nullptr);
    if (!window) throw NoDisplayError(kNoDisplay);
  }
  ~Glfw() {
    if (window) glfwDestroyWindow(window);
    glfwTerminate();
  }
  GLFWwindow* window = nullptr;
};

// The sheet the window shows, which the mouse picks on: the simulated one while simulating.
const Sheet& shownSheet(const session::Document& doc) {
  const LiveSimulation* simulation = doc.core->simulation();
  return simulation ? simulation->sheet() : doc.session->current();
}

// PNG of a scene through the offscreen path, on the window's device.
void exportPng(const VulkanContext& context, const Scene& scene, VkExtent2D extent,
               const fs::path& path) {
  writeFileAtomically(path, encodePng(renderSceneOnce(context, scene, extent)));
}

// The design the window opens with, and where it autosaves.
struct Start {
  Design design;
  std::string name;  // the surface's, for the autosave and the exports, without an input
  std::string autosavePath;
};

Start chooseStart(const DesignerOptions& options) {
  Start start;
  if (options.resume) {
    start.name = kDefaultSurface;
    start.autosavePath = options.autosave.empty()
                             ? session::defaultAutosave(options.input, start.name)
                             : options.autosave;
    if (!fs::exists(start.autosavePath)) throw NoAutosaveError(start.autosavePath);
    start.design = loadDesign(start.autosavePath);
    return start;
  }
  // With a target and no sheet named, the sheet is chosen to match the target (issue 38, 4),
  // before any window: the catalogue surface `fit` would start from.
  studio::StudioStart chosen = studio::studioStart(options.input, options.target, kDefaultSurface);
  start.design = std::move(chosen.design);
  start.name = chosen.surfaceName;
  start.autosavePath = options.autosave.empty()
                           ? session::defaultAutosave(options.input, start.name)
                           : options.autosave;
  return start;
}

ContextOptions contextOptionsFor(GLFWwindow* window, bool validation) {
  ContextOptions contextOptions;
  std::uint32_t extensionCount = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
  for (std::uint32_t i = 0; i < extensionCount; ++i)
    contextOptions.instance.extensions.push_back(extensions[i]);
  contextOptions.instance.validation = validation || vulkanValidationAsked();
  contextOptions.device.extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  contextOptions.createSurface = [window](VkInstance instance) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    vkCheck(glfwCreateWindowSurface(instance, window, nullptr, &surface),
            "glfwCreateWindowSurface");
    return surface;
  };
  return contextOptions;
}

VkSampleCountFlagBits samplesFor(const VulkanContext& context, int msaa) {
  return msaa > 0 ? context.sampleCountUpTo(static_cast<VkSampleCountFlagBits>(msaa))
                  : context.interactiveSampleCount();
}

glm::dvec2 windowSize(GLFWwindow* window) {
  int x = 0, y = 0;
  glfwGetWindowSize(window, &x, &y);
  return glm::dvec2(std::max(x, 1), std::max(y, 1));
}

// Input state shared with the GLFW callbacks.
struct InputState {
  OrbitCamera camera;
  DesktopInput input;
  session::Document* doc = nullptr;
  glm::dvec2 mouse{0.0};
  bool orbiting = false, panning = false, quit = false;
  bool suggest = false;  // S: the panel's Suggest
  bool events = false;   // an event came since the last look (RedrawPacer::changed)
  double pendingWheel = 0.0;
};

// An event the window answers with frames (RedrawPacer).
void wake(GLFWwindow* window) {
  static_cast<InputState*>(glfwGetWindowUserPointer(window))->events = true;
}

// The mouse, wheel and keys into state; installed before ImGui's, so ImGui chains to them.
void installInputCallbacks(GLFWwindow* window, InputState& state) {
  glfwSetWindowUserPointer(window, &state);
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    auto& s = *static_cast<InputState*>(glfwGetWindowUserPointer(w));
    s.events = true;
    if (action == GLFW_PRESS && ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse)
      return;
    int x = 0, y = 0;
    glfwGetWindowSize(w, &x, &y);
    const Ray ray = s.camera.ray(s.mouse, std::max(x, 1), std::max(y, 1));
    if (button == GLFW_MOUSE_BUTTON_LEFT) {
      if (action == GLFW_PRESS)
        s.input.press(ray, shownSheet(*s.doc), s.doc->core->worldFromSheet(), s.camera.forward());
      else
        s.input.release();
    } else if (button == GLFW_MOUSE_BUTTON_RIGHT) {
      s.orbiting = action == GLFW_PRESS;
    } else if (button == GLFW_MOUSE_BUTTON_MIDDLE) {
      s.panning = action == GLFW_PRESS;
    }
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    auto& s = *static_cast<InputState*>(glfwGetWindowUserPointer(w));
    s.events = true;
    const glm::dvec2 delta = glm::dvec2(x, y) - s.mouse;
    s.mouse = {x, y};
    int width = 0, height = 0;
    glfwGetWindowSize(w, &width, &height);
    if (s.orbiting) s.camera.orbit(delta.x, delta.y);
    if (s.panning) s.camera.pan(delta.x, delta.y, height);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    auto& s = *static_cast<InputState*>(glfwGetWindowUserPointer(w));
    s.events = true;
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
    if (s.input.dragging())
      s.input.wheel(-dy);  // wheel towards the user brings the point nearer
    else
      s.camera.zoom(dy);
  });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
    auto& s = *static_cast<InputState*>(glfwGetWindowUserPointer(w));
    s.events = true;
    if (action != GLFW_PRESS) return;
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
    const bool ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    if (key == GLFW_KEY_ESCAPE) s.input.pulse(Button::Cancel);
    if (ctrl && key == GLFW_KEY_Z)
      s.input.pulse((mods & GLFW_MOD_SHIFT) ? Button::Redo : Button::Undo);
    if (ctrl && key == GLFW_KEY_Q) s.quit = true;
    // The target's suggestions (issue 27): S asks, T takes the one on offer, N offers another.
    if (!ctrl && key == GLFW_KEY_S) s.suggest = true;
    if (!ctrl && key == GLFW_KEY_T) s.input.pulse(Button::TakeSuggestion);
    if (!ctrl && key == GLFW_KEY_N) s.input.pulse(Button::NextSuggestion);
  });
  // The rest only wake the window (ImGui chains to the ones it uses).
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned) { wake(w); });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { wake(w); });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { wake(w); });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { wake(w); });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { wake(w); });
}

// One frame for --frame-times: its duration, the frame thread's CPU time in it (what the frame's
// own work costs, apart from the other threads and processes sharing the cores), and what the
// studio did in it ("suggest": a suggestion asked, "offered": one joined the frame).
struct FrameTime {
  float wallMs = 0.0f;
  float cpuMs = 0.0f;
  const char* note = "";
  // The window's rest before the frame, waiting for a change (RedrawPacer): not in wallMs.
  float waitedMs = 0.0f;
  // On a frame with a note: the process's CPU by thread group at its end (threadGroupCpuToken).
  std::string cpu;
  // Wall time of each step of the frame loop (DesignerWindow::run), to tell which one a slow
  // frame waited in.
  std::array<float, 7> phaseMs{};
};

double threadCpuMs() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
}

void writeFrameTimes(const std::string& path, const std::vector<FrameTime>& frameTimes) {
  std::string text;
  char line[160];
  for (const FrameTime& frame : frameTimes) {
    std::snprintf(line, sizeof line,
                  "%.3f %.3f phases=%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f waited=%.2f%s%s",
                  frame.wallMs, frame.cpuMs, frame.phaseMs[0], frame.phaseMs[1], frame.phaseMs[2],
                  frame.phaseMs[3], frame.phaseMs[4], frame.phaseMs[5], frame.phaseMs[6],
                  frame.waitedMs, *frame.note ? " " : "", frame.note);
    text += line;
    text += frame.cpu.empty() ? "\n" : " " + frame.cpu + "\n";
  }
  writeFileAtomically(path, text);
}

void throwOnValidationMessages(const VulkanContext& context) {
  if (context.validationMessageCount() == 0) return;
  throw VulkanError(std::to_string(context.validationMessageCount()) +
                    " Vulkan validation messages, the first: " +
                    context.validationMessages().front().substr(
                        0, context.validationMessages().front().find('\n')));
}

// The window, its device and panel over a document the caller keeps (with its target and
// files), which outlive it.
class DesignerWindow {
 public:
  DesignerWindow(const DesignerOptions& options, unsigned width, unsigned height,
                 const Start& start, session::Document& doc, studio::StudioTarget& goal,
                 session::SessionOutputs& outputs);
  // The simulation's GPU solver goes before the device it runs on (doc_ outlives the window).
  ~DesignerWindow() {
    if (doc_.core) doc_.core->endSimulation();
  }
  // Frames until the window closes or Ctrl+Q.
  void run();
  // After run: the last frame's screenshot, the frame times, the session's files.
  void finish();

 private:
  void initImGui();
  void startRecording();
  void frameView();  // the sheet and the target together (issue 38, 4)
  void replaceDocument(Design next, const std::string& name);
  void takeRevisedStart();  // the start `fit` would choose, once it is ready
  // One frame's steps, in order.
  void drawPanel();
  studio::StudioActions panelActions();
  InputFrame nextInput();
  void process(InputFrame& input);
  void followView();
  // sceneMade: called between making the scene and drawing it (--frame-times' phases).
  void drawScene(const InputFrame& input, const std::function<void()>& sceneMade);
  void timeFrame();
  // Waits, drawing nothing, until the pacer says the next frame is due.
  void waitForChange();

  const DesignerOptions& options_;
  const unsigned width_, height_;
  session::Document& doc_;
  studio::StudioTarget& goal_;
  session::SessionOutputs& outputs_;
  Glfw glfw_;
  GLFWwindow* const window_;
  VulkanContext context_;
  SwapchainTarget target_;
  FrameRing frames_;
  SceneRenderer renderer_;
  desktop::InteractionSheetTracker tracker_;
  VkDescriptorPool imguiPool_ = VK_NULL_HANDLE;
  // The 2D crease pattern as a side view on the right (docs/design.md 7), toggled in the panel.
  bool creasePatternPanel_;
  CreasePatternCache panelCache_;
  InputState state_;
  studio::StudioPanel panel_;  // shared with the headset
  studio::StudioStats stats_;  // what the window measures for the panel
  Ground ground_;
  Scene lastScene_;
  // What the view showed of the committed sheet: a fold that takes a sheet the view showed whole
  // out of it (a suggestion taken toward a target elsewhere) frames the view again; a view the
  // user zoomed into stays theirs.
  std::uint64_t viewedRevision_ = 0;
  const void* viewedSession_ = nullptr;
  bool sheetShown_ = true;
  const TriangleMesh* framedTarget_ = nullptr;
  RedrawPacer pacer_;      // when the next frame is drawn
  float waitedMs_ = 0.0f;  // the rest before this frame (FrameTime::waitedMs)
  std::vector<FrameTime> frameTimes_;
  std::array<float, 7> phaseMs_{};  // this frame's steps (FrameTime::phaseMs)
  double lastFrameCpuMs_ = 0.0;
  const char* frameNote_ = "";   // what the studio did this frame, for --frame-times
  SimulationPuller puller_;      // the mouse's pull of the simulated sheet
  LiveSolverFactory gpuSolver_;  // none: the device cannot run compute
  // Input time, which never goes backwards.
  Clock::time_point start_, lastFrame_;
  double lastTime_ = 0.0;
};

DesignerWindow::DesignerWindow(const DesignerOptions& options, unsigned width, unsigned height,
                               const Start& start, session::Document& doc,
                               studio::StudioTarget& goal, session::SessionOutputs& outputs)
    : options_(options),
      width_(width),
      height_(height),
      doc_(doc),
      goal_(goal),
      outputs_(outputs),
      glfw_(width, height),
      window_(glfw_.window),
      context_(contextOptionsFor(window_, options.validation)),
      target_(
          context_,
          [window = window_] {
            int w = 0, h = 0;
            glfwGetFramebufferSize(window, &w, &h);
            return VkExtent2D{std::uint32_t(std::max(w, 0)), std::uint32_t(std::max(h, 0))};
          },
          samplesFor(context_, options.msaa)),
      frames_(context_),
      renderer_(context_, target_),
      creasePatternPanel_(options.creasePatternPanel),
      panel_(outputs.wantsRecording(), kHelp),
      ground_(groundBelow(worldBounds(doc.session->fixed()))) {
  // ImGui, drawn in the scene pass (its MSAA sample count).
  imguiPool_ = createDescriptorPool(context_.device(), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                    16, VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
  ImGui::StyleColorsLight();
  state_.doc = &doc_;
  frameView();
  state_.input = DesktopInput(0.02 * sheetSize(doc_.session->initial()));
  installInputCallbacks(window_, state_);
  initImGui();
  panel_.setRecent(session::loadRecentDesigns());
  panel_.setTargetPath(options_.target);
  panel_.setDesktop(true);
  // The live simulation's Vulkan compute solver on the window's device (issue 39, 4).
  if (supportsLiveCompute(context_)) {
    gpuSolver_ = gpuLiveSolver(context_);
    panel_.setGpuSolverAvailable(true);
    panel_.setGpuSolver(options.gpu);
  } else if (options.gpu) {
    panel_.setMessage("--gpu: " + context_.deviceName() +
                      " cannot run compute shaders; simulating on the CPU");
  }
  // Save and the exports are named after the design: vase.curvefold.json opened saves to itself.
  panel_.nameDesign(options_.resume          ? start.autosavePath
                    : options_.input.empty() ? start.name
                                             : options_.input);
  // The window and the device exist: now the recording may be created (B8 of issue 13).
  if (outputs_.wantsRecording()) startRecording();
  viewedRevision_ = doc_.session->fixedRevision();
  viewedSession_ = doc_.session.get();
  framedTarget_ = goal_.mesh();
}

void DesignerWindow::initImGui() {
  // Installed after ours, so ImGui chains to them.
  ImGui_ImplGlfw_InitForVulkan(window_, true);
  ImGui_ImplVulkan_InitInfo imguiInfo{};
  imguiInfo.Instance = context_.instance();
  imguiInfo.PhysicalDevice = context_.physicalDevice();
  imguiInfo.Device = context_.device();
  imguiInfo.QueueFamily = context_.graphicsFamily();
  imguiInfo.Queue = context_.graphicsQueue();
  imguiInfo.DescriptorPool = imguiPool_;
  imguiInfo.MinImageCount = std::max(2u, target_.minImageCount());
  imguiInfo.ImageCount = std::max(imguiInfo.MinImageCount, target_.imageCount());
  imguiInfo.MSAASamples = target_.format().samples;
  ImGui_ImplVulkan_Init(&imguiInfo, target_.renderPass());
  // The font atlas, uploaded once with a one-off command buffer.
  Frame& frame = frames_.begin();
  ImGui_ImplVulkan_CreateFontsTexture(frame.commands);
  frames_.submit(frame);
  frames_.wait(frame);
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

void DesignerWindow::startRecording() {
  RecordingHeader header;
  header.source = "desktop";
  header.surface = doc_.recordingSurface();
  header.symmetry = doc_.recordingSymmetry();
  // The display's refresh rate paces the frames (informative; each frame carries its time).
  const GLFWvidmode* mode = glfwGetVideoMode(glfwGetPrimaryMonitor());
  header.rate = mode && mode->refreshRate > 0 ? double(mode->refreshRate) : 60.0;
  outputs_.startRecording(header);
}

void DesignerWindow::frameView() {
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  const float aspect = w > 0 && h > 0 ? float(w) / float(h) : float(width_) / float(height_);
  state_.camera = OrbitCamera::framing(
      studioBounds(doc_.session->fixed(), goal_.mesh(), doc_.core->worldFromSheet()), aspect);
}

void DesignerWindow::replaceDocument(Design next, const std::string& name) {
  session::Document fresh = session::makeDocument(next, name);
  doc_.core.reset();
  doc_ = std::move(fresh);
  goal_.documentReplaced();
  renderer_.markSheetReplaced();
  tracker_ = desktop::InteractionSheetTracker();
  state_.input = DesktopInput(0.02 * sheetSize(doc_.session->initial()));
  frameView();
  ground_ = groundBelow(worldBounds(doc_.session->fixed()));
}

void DesignerWindow::takeRevisedStart() {
  // Before the frame's input is read, so that a press meets the sheet it is drawn on. A live
  // simulation is the designer at work on the sheet open, as a fold is.
  std::optional<Design> revised = goal_.takeRevisedStart(doc_, doc_.core->simulation() != nullptr);
  if (!revised) return;
  replaceDocument(std::move(*revised), options_.input);
  frameNote_ = "start";
  std::cout << goal_.suggestionLine(*doc_.core) << std::endl;  // which sheet, where it is said
}

void DesignerWindow::run() {
  start_ = Clock::now();
  lastFrame_ = Clock::now();
  lastFrameCpuMs_ = threadCpuMs();
  while (!glfwWindowShouldClose(window_) && !state_.quit) {
    waitForChange();
    if (glfwWindowShouldClose(window_) || state_.quit) break;
    Clock::time_point phaseStart = Clock::now();
    std::size_t phase = 0;
    const auto endPhase = [&] {
      const Clock::time_point now = Clock::now();
      phaseMs_[phase++] =
          float(std::chrono::duration<double, std::milli>(now - phaseStart).count());
      phaseStart = now;
    };
    takeRevisedStart();
    glfwPollEvents();
    {
      const glm::dvec2 size = windowSize(window_);
      state_.input.mouseRay(state_.camera.ray(state_.mouse, size.x, size.y), shownSheet(doc_),
                            doc_.core->worldFromSheet());
    }
    endPhase();
    drawPanel();
    endPhase();
    InputFrame input = nextInput();
    endPhase();
    process(input);
    endPhase();
    followView();
    endPhase();
    drawScene(input, endPhase);
    endPhase();
    timeFrame();
    // Something that moves by itself is drawn again at once: a drag (the sheet is drawn a frame
    // behind it), the live simulation, the camera under a held button, a text field's cursor.
    pacer_.drawn(doc_.session->dragging() || doc_.core->simulation() != nullptr ||
                     state_.orbiting || state_.panning || ImGui::GetIO().WantTextInput,
                 Clock::now());
  }
  frames_.waitAll();
}

void DesignerWindow::waitForChange() {
  const Clock::time_point waitStart = Clock::now();
  // CURVEFOLD_REDRAW=always: every frame drawn at once, as before the pacer (to measure both).
  static const bool always = redrawAlways();
  while (!always) {
    if (state_.events) pacer_.changed();
    state_.events = false;
    if (goal_.hasNews()) pacer_.changed();
    const double wait = pacer_.wait(Clock::now());
    if (wait <= 0.0 || glfwWindowShouldClose(window_) || state_.quit) break;
    glfwWaitEventsTimeout(wait);
  }
  // The frame's duration starts here: the wait is the window's rest, not its work.
  const Clock::time_point now = Clock::now();
  waitedMs_ = float(std::chrono::duration<double, std::milli>(now - waitStart).count());
  lastFrame_ += now - waitStart;
  lastFrameCpuMs_ = threadCpuMs();
}

studio::StudioActions DesignerWindow::panelActions() {
  studio::StudioActions actions{
      [this](const Design& next, const std::string& name) { replaceDocument(next, name); },
      [this](Button button) { state_.input.pulse(button); },
      [this](const std::string& path) { exportPng(context_, lastScene_, target_.extent(), path); }};
  actions.foldedForm = [this]() -> std::optional<PdfPicture> {
    const RgbaImage image = renderSceneOnce(
        context_,
        sceneForSheet(doc_.session->fixed(), ViewPreset::Iso, 1.5f, /*creasePatternPanel=*/false),
        {1200, 800});
    return PdfPicture{image.width, image.height, image.pixels};
  };
  actions.loadTarget = [this](const std::string& path) {
    goal_.load(path, doc_);
    frameNote_ = "load";
  };
  actions.suggest = [this] {
    goal_.suggest(doc_);
    frameNote_ = "suggest";
  };
  actions.recentChanged = [this](const std::vector<std::string>& recent) {
    try {
      session::saveRecentDesigns(recent);
    } catch (const std::exception& e) {
      panel_.setMessage(std::string("recent designs not kept: ") + e.what());
    }
  };
  actions.failed = [](const std::string& problem) {
    std::cerr << "curvefold: warning: " << problem << std::endl;
  };
  return actions;
}

void DesignerWindow::drawPanel() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const studio::StudioActions actions = panelActions();
  stats_.targetLine = goal_.distanceLine();
  stats_.suggestionLine = goal_.suggestionLine(*doc_.core);
  panel_.draw(doc_, actions, stats_, creasePatternPanel_);
  ImGui::Render();
}

InputFrame DesignerWindow::nextInput() {
  const double time =
      std::max(lastTime_, std::chrono::duration<double>(Clock::now() - start_).count());
  lastTime_ = time;
  if (state_.suggest) {
    state_.suggest = false;
    try {
      goal_.suggest(doc_);
      frameNote_ = "suggest";
    } catch (const std::exception& e) {
      panel_.setMessage(e.what());
    }
  }
  InputFrame input = state_.input.frame(time);
  // The panel's simulation (issue 39, 4) is input like the mouse, so the recording keeps it.
  // A left drag on the simulated sheet pulls its nearest vertex toward the mouse's point (as
  // the headset's trigger does), recorded in the frame's pull.
  if (const std::optional<double> percent = panel_.simulationPercent()) {
    input.simulation = liveSimulationInput(*percent, doc_.session->fixed());
    input.simulation->solver = panel_.simulationSolver();
    input.simulation->pull = puller_.update(
        input.pointHand, input.pointHand.tracked, doc_.core->simulation(),
        doc_.core->worldFromSheet(), doc_.core->viewScale(), doc_.core->thresholds().selectPress,
        doc_.core->thresholds().selectRelease, std::numeric_limits<double>::infinity());
  } else {
    puller_.reset();
  }
  return input;
}

void DesignerWindow::process(InputFrame& input) {
  goal_.poll(doc_, input);  // a finished search's folds join the frame, and its recording
  if (!input.suggestions.empty()) frameNote_ = "offered";
  const Clock::time_point processStart = Clock::now();
  if (gpuSolver_) doc_.core->setGpuSolver(gpuSolver_);  // the core is new after Open or New
  // The CPU's steps overlap the drawing (one frame behind, the same states; performance.md).
  doc_.core->setSimulationOnWorker(true);
  doc_.core->process(input);
  if (doc_.session->dragging() || doc_.core->simulation())
    stats_.dragUpdateMs =
        std::chrono::duration<double, std::milli>(Clock::now() - processStart).count();
  outputs_.frame(input, doc_.core->events());
  for (const std::string& problem : outputs_.takeNewProblems()) {
    panel_.setMessage(problem);
    std::cerr << "curvefold: warning: " << problem << std::endl;
  }
}

void DesignerWindow::followView() {
  const glm::dvec2 size = windowSize(window_);
  const Sheet& fixed = doc_.session->fixed();
  if (goal_.mesh() != framedTarget_) {
    // A target swapped in (loaded off the frame): framed with the sheet.
    framedTarget_ = goal_.mesh();
    frameView();
    if (!*frameNote_) frameNote_ = "loaded";
  } else if (viewedSession_ == doc_.session.get() &&
             viewedRevision_ != doc_.session->fixedRevision()) {
    followSheet(state_.camera, sheetShown_,
                studioBounds(fixed, nullptr, doc_.core->worldFromSheet()),
                studioBounds(fixed, goal_.mesh(), doc_.core->worldFromSheet()), size.x, size.y);
  }
  if (viewedSession_ != doc_.session.get() || viewedRevision_ != doc_.session->fixedRevision()) {
    viewedSession_ = doc_.session.get();
    viewedRevision_ = doc_.session->fixedRevision();
    sheetShown_ = state_.camera.shows(
        studioBounds(doc_.session->fixed(), nullptr, doc_.core->worldFromSheet()), size.x, size.y);
  }
}

void DesignerWindow::drawScene(const InputFrame& input, const std::function<void()>& sceneMade) {
  tracker_.update(*doc_.core, renderer_);
  lastScene_ = sceneForInteraction(*doc_.core, input, state_.camera.camera(), ground_,
                                   {creasePatternPanel_, /*handMarkers=*/false, &panelCache_,
                                    goal_.mesh(), goal_.offeredResult(*doc_.core)});
  tracker_.describe(*doc_.core, lastScene_.sheet, panel_.strainColours());
  stats_.drawnTriangles = lastScene_.sheet.sheet->triangleCount();
  sceneMade();
  ImDrawData* panel = ImGui::GetDrawData();
  drawFrame(frames_, target_, renderer_, lastScene_, [panel](VkCommandBuffer commands) {
    ImGui_ImplVulkan_RenderDrawData(panel, commands);
  });
}

void DesignerWindow::timeFrame() {
  const Clock::time_point now = Clock::now();
  stats_.frameMs = std::chrono::duration<double, std::milli>(now - lastFrame_).count();
  lastFrame_ = now;
  const double cpuMs = threadCpuMs();
  if (!options_.frameTimes.empty()) {
    frameTimes_.push_back({float(stats_.frameMs), float(cpuMs - lastFrameCpuMs_), frameNote_,
                           waitedMs_, *frameNote_ ? threadGroupCpuToken(threadGroupCpu()) : "",
                           phaseMs_});
  }
  lastFrameCpuMs_ = threadCpuMs();  // the reading above is not the next frame's work
  frameNote_ = "";
}

void DesignerWindow::finish() {
  if (!options_.screenshotOnExit.empty())
    exportPng(context_, lastScene_, target_.extent(), options_.screenshotOnExit);
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  vkDestroyDescriptorPool(context_.device(), imguiPool_, nullptr);
  if (!options_.frameTimes.empty()) writeFrameTimes(options_.frameTimes, frameTimes_);
  if (!outputs_.finish()) throw FileError(outputs_.problems().back());
  throwOnValidationMessages(context_);
}

}  // namespace

void runDesigner(const DesignerOptions& options) {
  const unsigned width = options.width, height = options.height;
  const Start start = chooseStart(options);
  session::Document doc =
      session::makeDocument(start.design, options.resume ? start.autosavePath : options.input);
  // Read and checked before any window or file: a bad target is one line and nothing else.
  // The search below the frame: lavapipe draws on the same cores (docs/performance.md).
  studio::StudioTarget goal(false, SuggestionWorker::kDefaultTimeLimit, {},
                            SuggestionWorker::kYieldToFrames);
  if (!options.target.empty()) goal.loadNow(options.target, doc);
  // Declared after doc, so that it finishes (saves) before doc goes away, on every way out.
  session::SessionOutputs outputs(start.autosavePath, options.record,
                                  [&doc] { return doc.design(); },
                                  {{options.target, "the target"}});
  if (outputs.wantsRecording()) session::startFromCommittedFolds(doc);
  // The window opens on the rule's sheet at once; the start `fit` would choose (its first step's
  // revisions: seconds) comes off the frame and replaces it while the designer has not begun
  // (StudioTarget::takeRevisedStart). Not with --record: the recording starts from the sheet open.
  if (options.input.empty() && !options.resume && !options.target.empty() &&
      !outputs.wantsRecording())
    goal.reviseStart(doc);
  DesignerWindow window(options, width, height, start, doc, goal, outputs);
  window.run();
  window.finish();
}

}  // namespace curvefold::desktop
