// `curvefold design` and plain `curvefold`: the desktop designer (docs/design.md 5 and 7). A GLFW
// window with a SwapchainTarget, the shared SceneRenderer, an ImGui panel, and DesktopInput
// feeding the one InteractionCore; recorded with --record, autosaved after every committed fold.
// GLFW declares glfwCreateWindowSurface only with Vulkan's header.
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "app/desktop/desktop_input.hpp"
#include "app/document.hpp"
#include "app/interaction_scene.hpp"
#include "app/recent_designs.hpp"
#include "app/session_outputs.hpp"
#include "app/studio_panel.hpp"
#include "app/studio_target.hpp"
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
#include "engine/text/decimal.hpp"
#include "engine/text/excerpt.hpp"
#include "sim_input/player.hpp"

namespace curvefold::desktop {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kNoDisplay =
    "no display for the designer window; use `curvefold replay` or `curvefold render` instead";
constexpr const char* kDefaultSurface = "square";

struct DesignerOptions {
  std::string input;  // design file, surface name, or empty for the default surface
  std::string record, autosave, screenshotOnExit, size = "1280x720";
  std::string target;      // a target shape (OBJ) to fold toward
  std::string frameTimes;  // where to write each frame's duration when the window closes
  bool resume = false;
  bool validation = false;
  bool creasePatternPanel = false;
  int msaa = 0;  // samples per pixel; 0: the device's interactive default
};

// GLFW's window, created and destroyed with glfwInit/glfwTerminate around it.
struct Glfw {
  Glfw() {
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr)
      throw cli::NoDisplayError(kNoDisplay);
    glfwSetErrorCallback([](int, const char*) {});  // glfwInit's failure is reported below
    if (!glfwInit()) throw cli::NoDisplayError(kNoDisplay);
    if (!glfwVulkanSupported()) {
      glfwTerminate();
      throw std::runtime_error("no Vulkan loader usable with the window system");
    }
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

void runDesigner(const DesignerOptions& options) {
  unsigned width = 1280, height = 720;
  if (!readSize(options.size, 64u, 8192u, width, height))
    throw cli::UsageError("--size: expected WxH from 64 to 8192, got " +
                          quotedExcerpt(options.size));
  // With a target and no sheet named, the sheet is chosen to match the target (issue 38, 4),
  // before any window: the catalogue surface `fit` would start from.
  const bool startFromTarget = !options.resume && options.input.empty() && !options.target.empty();
  Design design;
  if (startFromTarget) design = studio::startForTarget(options.target);
  const std::string startName =
      startFromTarget ? std::get<GeneratedSurface>(design.surface).generator : kDefaultSurface;
  const std::string autosavePath = options.autosave.empty()
                                       ? session::defaultAutosave(options.input, startName)
                                       : options.autosave;
  if (options.resume) {
    if (!fs::exists(autosavePath))
      throw cli::UsageError("--resume: no autosave at " + autosavePath);
    design = loadDesign(autosavePath);
  } else if (!startFromTarget) {
    design = session::designFor(options.input, kDefaultSurface);
  }
  session::Document doc =
      session::makeDocument(design, options.resume ? autosavePath : options.input);
  // Read and checked before any window or file: a bad target is one line and nothing else.
  studio::StudioTarget goal;
  if (!options.target.empty()) goal.loadNow(options.target, doc);
  // Declared after doc, so that it finishes (saves) before doc goes away, on every way out.
  session::SessionOutputs outputs(autosavePath, options.record, [&doc] { return doc.design(); },
                                  {{options.target, "the target"}});
  if (outputs.wantsRecording()) session::startFromCommittedFolds(doc);

  Glfw glfw;
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfw.window = glfwCreateWindow(int(width), int(height), "curvefold", nullptr, nullptr);
  if (!glfw.window) throw cli::NoDisplayError(kNoDisplay);
  GLFWwindow* window = glfw.window;

  ContextOptions contextOptions;
  std::uint32_t extensionCount = 0;
  const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
  for (std::uint32_t i = 0; i < extensionCount; ++i)
    contextOptions.instance.extensions.push_back(extensions[i]);
  contextOptions.instance.validation =
      options.validation || (std::getenv("CURVEFOLD_VK_VALIDATION") &&
                             std::string(std::getenv("CURVEFOLD_VK_VALIDATION")) == "1");
  contextOptions.device.extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  contextOptions.createSurface = [window](VkInstance instance) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    vkCheck(glfwCreateWindowSurface(instance, window, nullptr, &surface),
            "glfwCreateWindowSurface");
    return surface;
  };
  VulkanContext context(contextOptions);
  const VkSampleCountFlagBits samples =
      options.msaa > 0 ? context.sampleCountUpTo(static_cast<VkSampleCountFlagBits>(options.msaa))
                       : context.interactiveSampleCount();
  SwapchainTarget target(
      context,
      [window] {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window, &w, &h);
        return VkExtent2D{std::uint32_t(std::max(w, 0)), std::uint32_t(std::max(h, 0))};
      },
      samples);
  FrameRing frames(context);
  SceneRenderer renderer(context, target);
  desktop::InteractionSheetTracker tracker;

  // ImGui, drawn in the scene pass (its MSAA sample count).
  const VkDescriptorPool imguiPool =
      createDescriptorPool(context.device(), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16,
                           VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
  ImGui::StyleColorsLight();

  // The 2D crease pattern as a side view on the right (docs/design.md 7), toggled in the panel.
  bool creasePatternPanel = options.creasePatternPanel;
  CreasePatternCache panelCache;

  // Input state shared with the GLFW callbacks.
  struct State {
    OrbitCamera camera;
    DesktopInput input;
    session::Document* doc = nullptr;
    glm::dvec2 mouse{0.0};
    bool orbiting = false, panning = false, quit = false;
    bool suggest = false;  // S: the panel's Suggest
    double pendingWheel = 0.0;
  } state;
  state.doc = &doc;
  // The sheet and the target together (issue 38, 4).
  auto frameView = [&] {
    int w = 0, h = 0;
    glfwGetWindowSize(window, &w, &h);
    const float aspect = w > 0 && h > 0 ? float(w) / float(h) : float(width) / float(height);
    state.camera = OrbitCamera::framing(
        studioBounds(doc.session->fixed(), goal.mesh(), doc.core->worldFromSheet()), aspect);
  };
  frameView();
  state.input = DesktopInput(0.02 * sheetSize(doc.session->initial()));
  glfwSetWindowUserPointer(window, &state);
  auto windowSize = [](GLFWwindow* w) {
    int x = 0, y = 0;
    glfwGetWindowSize(w, &x, &y);
    return glm::dvec2(std::max(x, 1), std::max(y, 1));
  };
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    auto& s = *static_cast<State*>(glfwGetWindowUserPointer(w));
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
    auto& s = *static_cast<State*>(glfwGetWindowUserPointer(w));
    const glm::dvec2 delta = glm::dvec2(x, y) - s.mouse;
    s.mouse = {x, y};
    int width = 0, height = 0;
    glfwGetWindowSize(w, &width, &height);
    if (s.orbiting) s.camera.orbit(delta.x, delta.y);
    if (s.panning) s.camera.pan(delta.x, delta.y, height);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    auto& s = *static_cast<State*>(glfwGetWindowUserPointer(w));
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
    if (s.input.dragging())
      s.input.wheel(-dy);  // wheel towards the user brings the point nearer
    else
      s.camera.zoom(dy);
  });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
    auto& s = *static_cast<State*>(glfwGetWindowUserPointer(w));
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
  // Installed after ours, so ImGui chains to them.
  ImGui_ImplGlfw_InitForVulkan(window, true);
  ImGui_ImplVulkan_InitInfo imguiInfo{};
  imguiInfo.Instance = context.instance();
  imguiInfo.PhysicalDevice = context.physicalDevice();
  imguiInfo.Device = context.device();
  imguiInfo.QueueFamily = context.graphicsFamily();
  imguiInfo.Queue = context.graphicsQueue();
  imguiInfo.DescriptorPool = imguiPool;
  imguiInfo.MinImageCount = std::max(2u, target.minImageCount());
  imguiInfo.ImageCount = std::max(imguiInfo.MinImageCount, target.imageCount());
  imguiInfo.MSAASamples = target.format().samples;
  ImGui_ImplVulkan_Init(&imguiInfo, target.renderPass());
  {
    // The font atlas, uploaded once with a one-off command buffer.
    Frame& frame = frames.begin();
    ImGui_ImplVulkan_CreateFontsTexture(frame.commands);
    frames.submit(frame);
    frames.wait(frame);
    ImGui_ImplVulkan_DestroyFontUploadObjects();
  }

  // The panel (shared with the headset) and what the window measures for it.
  studio::StudioPanel panel(
      outputs.wantsRecording(),
      "Left drag: fold (simulating: pull the paper; wheel: depth). Right: orbit, middle: pan, "
      "wheel: zoom. Esc "
      "cancels, Ctrl+Z / Ctrl+Shift+Z undo/redo, Ctrl+Q quits. With a target: S "
      "suggests a fold, T takes it, N offers another.");
  panel.setRecent(session::loadRecentDesigns());
  panel.setTargetPath(options.target);
  panel.setDesktop(true);
  // Save and the exports are named after the design: vase.curvefold.json opened saves to itself.
  panel.nameDesign(options.resume          ? autosavePath
                   : options.input.empty() ? startName
                                           : options.input);
  studio::StudioStats stats;
  Ground ground = groundBelow(worldBounds(doc.session->fixed()));
  Scene lastScene;

  auto replaceDocument = [&](Design next, const std::string& name) {
    session::Document fresh = session::makeDocument(next, name);
    doc.core.reset();
    doc = std::move(fresh);
    goal.documentReplaced();
    renderer.markSheetReplaced();
    tracker = desktop::InteractionSheetTracker();
    state.input = DesktopInput(0.02 * sheetSize(doc.session->initial()));
    frameView();
    ground = groundBelow(worldBounds(doc.session->fixed()));
  };

  // The window and the device exist: now the recording may be created (B8 of issue 13).
  if (outputs.wantsRecording()) {
    RecordingHeader header;
    header.source = "desktop";
    header.surface = doc.recordingSurface();
    header.symmetry = doc.recordingSymmetry();
    // The display's refresh rate paces the frames (informative; each frame carries its time).
    const GLFWvidmode* mode = glfwGetVideoMode(glfwGetPrimaryMonitor());
    header.rate = mode && mode->refreshRate > 0 ? double(mode->refreshRate) : 60.0;
    outputs.startRecording(header);
  }

  // What the view showed of the committed sheet: a fold that takes a sheet the view showed whole
  // out of it (a suggestion taken toward a target elsewhere) frames the view again; a view the
  // user zoomed into stays theirs.
  std::uint64_t viewedRevision = doc.session->fixedRevision();
  const void* viewedSession = doc.session.get();
  bool sheetShown = true;
  const TriangleMesh* framedTarget = goal.mesh();
  std::vector<float> frameTimes;
  SimulationPuller puller;  // the mouse's pull of the simulated sheet

  const Clock::time_point start = Clock::now();
  double lastTime = 0.0;
  Clock::time_point lastFrame = Clock::now();
  while (!glfwWindowShouldClose(window) && !state.quit) {
    glfwPollEvents();
    {
      const glm::dvec2 size = windowSize(window);
      state.input.mouseRay(state.camera.ray(state.mouse, size.x, size.y), shownSheet(doc),
                           doc.core->worldFromSheet());
    }
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    studio::StudioActions actions{
        [&](const Design& next, const std::string& name) { replaceDocument(next, name); },
        [&](Button button) { state.input.pulse(button); },
        [&](const std::string& path) { exportPng(context, lastScene, target.extent(), path); }};
    actions.foldedForm = [&]() -> std::optional<PdfPicture> {
      const RgbaImage image = renderSceneOnce(
          context,
          sceneForSheet(doc.session->fixed(), ViewPreset::Iso, 1.5f, /*creasePatternPanel=*/false),
          {1200, 800});
      return PdfPicture{image.width, image.height, image.pixels};
    };
    actions.loadTarget = [&](const std::string& path) { goal.load(path, doc); };
    actions.suggest = [&] { goal.suggest(doc); };
    stats.targetLine = goal.distanceLine();
    stats.suggestionLine = goal.suggestionLine(*doc.core);
    actions.recentChanged = [&panel](const std::vector<std::string>& recent) {
      try {
        session::saveRecentDesigns(recent);
      } catch (const std::exception& e) {
        panel.setMessage(std::string("recent designs not kept: ") + e.what());
      }
    };
    actions.failed = [](const std::string& problem) {
      std::cerr << "curvefold: warning: " << problem << std::endl;
    };
    panel.draw(doc, actions, stats, creasePatternPanel);
    ImGui::Render();

    // Input into the core; time never goes backwards.
    const double time =
        std::max(lastTime, std::chrono::duration<double>(Clock::now() - start).count());
    lastTime = time;
    if (state.suggest) {
      state.suggest = false;
      try {
        goal.suggest(doc);
      } catch (const std::exception& e) {
        panel.setMessage(e.what());
      }
    }
    InputFrame input = state.input.frame(time);
    // The panel's simulation (issue 39, 4) is input like the mouse, so the recording keeps it.
    // A left drag on the simulated sheet pulls its nearest vertex toward the mouse's point (as
    // the headset's trigger does), recorded in the frame's pull.
    if (const std::optional<double> percent = panel.simulationPercent()) {
      input.simulation = liveSimulationInput(*percent, doc.session->fixed());
      input.simulation->pull = puller.update(
          input.pointHand, input.pointHand.tracked, doc.core->simulation(),
          doc.core->worldFromSheet(), doc.core->viewScale(), doc.core->thresholds().selectPress,
          doc.core->thresholds().selectRelease, std::numeric_limits<double>::infinity());
    } else {
      puller.reset();
    }
    goal.poll(doc, input);  // a finished search's folds join the frame, and its recording
    const Clock::time_point processStart = Clock::now();
    doc.core->process(input);
    if (doc.session->dragging() || doc.core->simulation())
      stats.dragUpdateMs =
          std::chrono::duration<double, std::milli>(Clock::now() - processStart).count();
    outputs.frame(input, doc.core->events());
    for (const std::string& problem : outputs.takeNewProblems()) {
      panel.setMessage(problem);
      std::cerr << "curvefold: warning: " << problem << std::endl;
    }

    {
      const glm::dvec2 size = windowSize(window);
      if (goal.mesh() != framedTarget) {
        // A target swapped in (loaded off the frame): framed with the sheet.
        framedTarget = goal.mesh();
        frameView();
      } else if (viewedSession == doc.session.get() &&
                 viewedRevision != doc.session->fixedRevision()) {
        followSheet(state.camera, sheetShown,
                    studioBounds(doc.session->fixed(), nullptr, doc.core->worldFromSheet()),
                    studioBounds(doc.session->fixed(), goal.mesh(), doc.core->worldFromSheet()),
                    size.x, size.y);
      }
      if (viewedSession != doc.session.get() || viewedRevision != doc.session->fixedRevision()) {
        viewedSession = doc.session.get();
        viewedRevision = doc.session->fixedRevision();
        sheetShown = state.camera.shows(
            studioBounds(doc.session->fixed(), nullptr, doc.core->worldFromSheet()), size.x,
            size.y);
      }
    }
    tracker.update(*doc.core, renderer);
    lastScene = sceneForInteraction(*doc.core, input, state.camera.camera(), ground,
                                    {creasePatternPanel, /*handMarkers=*/false, &panelCache,
                                     goal.mesh(), goal.offeredResult(*doc.core)});
    tracker.describe(*doc.core, lastScene.sheet, panel.strainColours());
    stats.drawnTriangles = lastScene.sheet.sheet->triangleCount();
    ImDrawData* panel = ImGui::GetDrawData();
    drawFrame(frames, target, renderer, lastScene, [panel](VkCommandBuffer commands) {
      ImGui_ImplVulkan_RenderDrawData(panel, commands);
    });
    const Clock::time_point now = Clock::now();
    stats.frameMs = std::chrono::duration<double, std::milli>(now - lastFrame).count();
    lastFrame = now;
    if (!options.frameTimes.empty()) frameTimes.push_back(float(stats.frameMs));
  }
  frames.waitAll();
  if (!options.screenshotOnExit.empty())
    exportPng(context, lastScene, target.extent(), options.screenshotOnExit);
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  vkDestroyDescriptorPool(context.device(), imguiPool, nullptr);
  if (!options.frameTimes.empty()) {
    std::string text;
    char line[32];
    for (const float ms : frameTimes) {
      std::snprintf(line, sizeof line, "%.3f\n", ms);
      text += line;
    }
    writeFileAtomically(options.frameTimes, text);
  }
  if (!outputs.finish()) throw FileError(outputs.problems().back());
  if (context.validationMessageCount() > 0)
    throw VulkanError(std::to_string(context.validationMessageCount()) +
                      " Vulkan validation messages, the first: " +
                      context.validationMessages().front().substr(
                          0, context.validationMessages().front().find('\n')));
}

}  // namespace

}  // namespace curvefold::desktop

// The command line's entry points into the window.
namespace curvefold::cli {

void addDesignCommand(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("design", "Open the desktop designer window (needs a display)");
  auto options = std::make_shared<desktop::DesignerOptions>();
  command->add_option("INPUT", options->input,
                      "Design file (*.curvefold.json) or surface name (default: square)");
  addSessionFileOptions(command, options->record, options->autosave, options->target,
                        "after every committed fold");
  command->add_flag("--resume", options->resume, "Start from the autosaved design");
  command->add_flag("--crease-pattern-panel", options->creasePatternPanel,
                    "Show the crease pattern as a side view (also a checkbox in the panel)");
  command->add_option("--size", options->size, "Window size WxH (default 1280x720)");
  command
      ->add_option("--msaa", options->msaa,
                   "Samples per pixel (default: 4 on a GPU, 1 on a CPU driver such as lavapipe)")
      ->check(CLI::IsMember({1, 2, 4, 8}));
  command->add_option("--screenshot-on-exit", options->screenshotOnExit,
                      "Write the last frame's scene to this PNG when the window closes");
  command->add_option("--frame-times", options->frameTimes,
                      "Write each frame's duration (ms, one a line) to this file when the window "
                      "closes");
  command->callback([options] { desktop::runDesigner(*options); });
}

void runDefaultDesigner() {
  desktop::runDesigner(desktop::DesignerOptions{});
}

}  // namespace curvefold::cli
