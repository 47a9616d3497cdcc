#include "app/xr/xr_app.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include "app/desktop/gpu_live_solver.hpp"
#include "app/desktop/interaction_scene.hpp"
#include "app/session/recent_designs.hpp"
#include "app/studio/headset_studio.hpp"
#include "app/studio/studio_target.hpp"
#include "app/xr/panel_texture.hpp"
#include "app/xr/xr_vulkan_graphics.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/output_set.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/image.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/render/sheet_tracker.hpp"
#include "engine/text/input_path.hpp"
#include "interaction/xr/xr_check.hpp"
#include "interaction/xr/xr_input.hpp"
#include "sim_input/recorder.hpp"
#include "sim_input/recording.hpp"

namespace curvefold::xr {

namespace fs = std::filesystem;

namespace {

constexpr const char* kDefaultSurface = "square";
constexpr const char* kDesktopInstead = "; `curvefold design` opens the desktop window instead";

// What the runtime lacks, naming the option of `curvefold xr` that asked for it.
[[noreturn]] void throwNamingOption(const XrMissingFeature& e) {
  throw XrError(
      std::string(e.what()) + (e.feature() == XrFeature::Headless ? " (needed for --headless)"
                                                                  : " (needed for --hands)"),
      e.result());
}

// The crease pattern on a card held beside the non-dominant hand, outside it so it never covers
// the sheet: 16 cm across, in the plane of the hand's x and y axes.
void addHeldPanel(Scene& scene, const CreasePatternPanel& panel, const Pose& hand, HandSide side) {
  constexpr double kWidth = 0.16;
  const glm::dvec2 low(panel.min), high(panel.max);
  const glm::dvec2 span = glm::max(high - low, glm::dvec2(1e-9));
  const double scale = kWidth / std::max(span.x, span.y);
  const glm::dvec2 centre = 0.5 * (low + high);
  const double outward = side == HandSide::Left ? -1.0 : 1.0;
  const glm::dvec3 origin(outward * (0.06 + 0.5 * kWidth), 0.05, 0.0);
  auto world = [&](const glm::dvec2& p) {
    return glm::vec3(hand.apply(origin + glm::dvec3((p - centre) * scale, 0.0)));
  };
  for (const LineSegment& line : panel.lines)
    scene.lines.push_back({world(glm::dvec2(line.a)), world(glm::dvec2(line.b)), line.color});
  // The card's edge, a little outside the pattern.
  const glm::dvec2 half = 0.5 * span * 1.08;
  const glm::dvec2 corners[4] = {
      centre + glm::dvec2(-half.x, -half.y), centre + glm::dvec2(half.x, -half.y),
      centre + glm::dvec2(half.x, half.y), centre + glm::dvec2(-half.x, half.y)};
  for (int i = 0; i < 4; ++i)
    scene.lines.push_back(
        {world(corners[i]), world(corners[(i + 1) % 4]), {0.35f, 0.35f, 0.38f, 1.0f}});
}

}  // namespace

XrApp::XrApp(const XrAppOptions& options) : options_(options) {
  Design design;
  Pose sheetFrame = defaultSheetFrame();
  HandSide handedness = options.leftHanded ? HandSide::Left : HandSide::Right;
  startName_ = kDefaultSurface;
  if (hasExtension(options.input, ".jsonl")) {
    // A recording: its surface, sheet frame and hands, to watch it through the XR path.
    const Recording recording = readRecording(options.input, {.allowTruncated = true});
    design = {recording.header.surface, {}, recording.header.symmetry};
    sheetFrame = recording.header.sheetFrame;
    if (!options.leftHanded) handedness = recording.header.handedness;
  } else {
    // With a target and no sheet named, the sheet matches the target, as in the desktop window
    // (issue 38, 4).
    studio::StudioStart start = studio::studioStart(options.input, options.target, kDefaultSurface);
    design = std::move(start.design);
    startName_ = std::move(start.surfaceName);
  }
  doc_ = session::makeDocument(design, options.input, sheetFrame, handedness);
  autosave_ = options.autosave.empty() ? session::defaultAutosave(options.input, startName_)
                                       : options.autosave;
  outputs_ = std::make_unique<session::SessionOutputs>(
      autosave_, options.record, [this] { return doc_.design(); },
      std::vector<NamedInput>{
          {options.target, "the target"},
          {hasExtension(options.input, ".jsonl") ? options.input : "", "the recording watched"}});
  if (outputs_->wantsRecording()) {
    // A recording starts from its header's surface: the opened folds become that surface, and
    // stay in the design (baseFolds).
    session::startFromCommittedFolds(doc_);
    recordingHeader_.source = "openxr";
    recordingHeader_.handedness = handedness;
    recordingHeader_.sheetFrame = sheetFrame;
    recordingHeader_.surface = doc_.recordingSurface();
    recordingHeader_.symmetry = doc_.recordingSymmetry();
  }

  if (!options.headless)
    graphics_ = std::make_unique<XrVulkanGraphics>(options.validation, options.multiview);
  makeStudio(sheetFrame);
  if (outputs_->wantsRecording())
    recordingHeader_.studio = RecordingHeader::Studio{studio_->panel().recent()};

  XrProgramOptions programOptions;
  programOptions.handTracking =
      options.hands ? XrHandTrackingUse::Required : XrHandTrackingUse::Auto;
  try {
    program_ = std::make_unique<XrProgram>(programOptions, graphics_.get());
  } catch (const XrMissingFeature& e) {
    throwNamingOption(e);
  } catch (const XrError& e) {
    // The interaction layer names no command; the front end says where else to fold.
    if (std::string(e.what()) == kNoXrRuntime)
      throw XrError(std::string(kNoXrRuntime) + kDesktopInstead, e.result());
    throw;
  }
  input_ = std::make_unique<XrInput>(program_->instance(), program_->handTrackingEnabled(),
                                     options.hands);
  tracker_ = std::make_unique<desktop::InteractionSheetTracker>();
  if (graphics_) {
    graphics_->setBeforeEyes([this](VkCommandBuffer commands) {
      if (panelTexture_ && studio_->drawData())
        panelTexture_->record(commands, studio_->drawData());
    });
  }
  if (graphics_)
    graphics_->setEyeScene(
        [this](std::span<const Camera> cameras) -> const Scene& { return eyeScene(cameras); });
  // The stage's floor, under the sheet.
  ground_.height = 0.0f;
  ground_.centre = {float(sheetFrame.position.x), float(sheetFrame.position.z)};
  ground_.spacing = 0.25f;
  ground_.halfCount = 8;
  summary_.runtime = program_->runtimeName();
  summary_.autosave = autosave_;
}

XrApp::~XrApp() {
  if (doc_.core) doc_.core->endSimulation();  // a GPU solver goes before the device (graphics_)
}

void XrApp::makeStudio(const Pose& sheetFrame) {
  studio::HeadsetStudioOptions options;
  options.exportDir = options_.exportDir;
  // Strings moved in, not assigned from const char*: GCC 12 inlines assign(const char*) here into
  // a false -Wrestrict.
  if (options.exportDir.empty()) {
    std::string parent = fs::path(autosave_).parent_path().string();
    options.exportDir = parent.empty() ? std::string(".") : std::move(parent);
  }
  options.name = options_.input.empty() ? startName_ : options_.input;
  options.recent = session::loadRecentDesigns();
  options.target = options_.target;
  options.searchNice = SuggestionWorker::kYieldToFrames;  // the frame and the eyes first
  options.sheetFrame = sheetFrame;
  studio::HeadsetStudioHost host;
  host.documentReplacing = [this](const std::string& name) {
    // The design left behind keeps its autosave; the next gets its own.
    outputs_->switchAutosave(session::nextAutosave(outputs_->autosavePath(), name));
  };
  host.documentReplaced = [this] {
    if (graphics_ && graphics_->renderer()) graphics_->renderer()->markSheetReplaced();
    tracker_ = std::make_unique<desktop::InteractionSheetTracker>();
    summary_.autosave = outputs_->autosavePath();
  };
  host.writeFile = [](const std::string& path,
                      const std::function<void(const std::string&)>& write) {
    const fs::path parent = fs::path(path).parent_path();
    std::error_code error;
    if (!parent.empty()) fs::create_directories(parent, error);
    if (error) throw FileError("cannot create " + parent.string() + ": " + error.message());
    write(path);
  };
  if (graphics_)
    host.exportPng = [this](const std::string& path) {
      // The design as a picture (iso view with its crease pattern), on the headset's device.
      if (!graphics_->context()) throw VulkanError("no Vulkan device yet for " + path);
      const Scene picture = sceneForSheet(doc_.session->fixed(), ViewPreset::Iso, 16.0f / 9.0f,
                                          /*creasePatternPanel=*/true);
      writeFileAtomically(path,
                          encodePng(renderSceneOnce(*graphics_->context(), picture, {1280, 720})));
    };
  if (graphics_)
    host.foldedForm = [this]() -> std::optional<PdfPicture> {
      if (!graphics_->context()) return std::nullopt;
      const RgbaImage image = renderSceneOnce(
          *graphics_->context(),
          sceneForSheet(doc_.session->fixed(), ViewPreset::Iso, 1.5f, /*creasePatternPanel=*/false),
          {1200, 800});
      return PdfPicture{image.width, image.height, image.pixels};
    };
  // A failed export (a full or read-only --export-dir) is said beyond the panel: on stderr at
  // once and in the summary at the end.
  host.failed = [this](const std::string& problem) {
    std::cerr << "curvefold: warning: " << problem << std::endl;
    summary_.problems.push_back(problem);
  };
  host.recentChanged = [](const std::vector<std::string>& recent) {
    try {
      session::saveRecentDesigns(recent);
    } catch (const std::exception& e) {
      std::cerr << "curvefold: warning: recent designs not kept: " << e.what() << std::endl;
    }
  };
  studio_ = std::make_unique<studio::HeadsetStudio>(doc_, std::move(options), std::move(host));
}

bool XrApp::startSession() {
  try {
    if (!program_->findSystem()) return false;
  } catch (const XrMissingFeature& e) {
    throwNamingOption(e);
  }
  program_->createSession();
  input_->attach(program_->session(), program_->tracksHands());
  ++summary_.sessions;
  return true;
}

bool XrApp::sessionRunning() const {
  return program_->running();
}

bool XrApp::pollEvents() {
  const XrPollResult result = program_->pollEvents();
  if (result.profilesChanged) summary_.profiles = input_->currentProfiles();
  if (result.instanceLost) summary_.instanceLost = true;
  restart_ = result.restartSession;
  return !result.exitLoop;
}

void XrApp::processInput(XrTime displayTime) {
  if (!haveFirstTime_) {
    firstTime_ = displayTime;
    haveFirstTime_ = true;
  }
  // Seconds since the first focused frame, on the runtime's clock, never going back.
  const double seconds = std::max(lastSeconds_, double(displayTime - firstTime_) * 1e-9);
  lastSeconds_ = seconds;
  InputFrame input;
  if (!input_->poll(program_->baseSpace(), displayTime, doc_.core->handedness(), seconds, input))
    return;
  const HandSide handedness = doc_.core->handedness();
  startRecording();
  // The live simulation's Vulkan compute solver on the headset's device (issue 39, 4), offered
  // in the panel once the device exists; the core is new after Open or New.
  const VulkanContext* context = graphics_ ? graphics_->context() : nullptr;  // none: headless
  if (context != gpuContext_) {
    doc_.core->endSimulation();  // its solver may be on the device that went
    gpuContext_ = context;
    gpuSolver_ = {};
    if (context && desktop::supportsLiveCompute(*context))
      gpuSolver_ = desktop::gpuLiveSolver(*context);
    studio_->panel().setGpuSolverAvailable(bool(gpuSolver_));
  }
  if (gpuSolver_) doc_.core->setGpuSolver(gpuSolver_);
  studio_->process(input, stats_);
  lastInput_ = input;
  ++summary_.framesProcessed;
  if (input_->usesHands()) ++summary_.handFrames;
  input_->applyHaptics(doc_.core->haptics(), handedness);
  outputs_->frame(input, doc_.core->events());
  for (const std::string& problem : outputs_->takeNewProblems()) {
    std::cerr << "curvefold: warning: " << problem << std::endl;
    summary_.problems.push_back(problem);
  }
}

// The file is made with the first focused frame, so a session that never starts leaves none, the
// header's rate is the runtime's (not a nominal 90 Hz), and its source says whether bare hands
// began it.
void XrApp::startRecording() {
  if (!outputs_->wantsRecording() || outputs_->recording()) return;
  recordingHeader_.rate = period_ > 0 ? 1e9 / double(period_) : 90.0;
  recordingHeader_.source = options_.hands || input_->usesHands() ? "hands" : "openxr";
  outputs_->startRecording(recordingHeader_);
}

void XrApp::buildScene() {
  if (SceneRenderer* renderer = graphics_->renderer()) {
    tracker_->update(*doc_.core, *renderer);
    if (!panelTexture_) {
      const glm::ivec2 pixels = studio_->pixels();
      panelTexture_ = std::make_unique<PanelTexture>(
          *graphics_->context(), studio_->context(),
          VkExtent2D{std::uint32_t(pixels.x), std::uint32_t(pixels.y)},
          graphics_->framesInFlight());
    }
    // A new renderer (after a lost session) is given the panel's picture before its first frame.
    if (texturedRenderer_ != graphics_->rendererGeneration()) {
      renderer->setWorldPanelTexture(panelTexture_->view(), panelTexture_->sampler());
      texturedRenderer_ = graphics_->rendererGeneration();
    }
  }
  desktop::InteractionSceneOptions sceneOptions;
  sceneOptions.target = studio_->goal().mesh();
  sceneOptions.offeredResult = studio_->goal().offeredResult(*doc_.core);
  scene_ = desktop::sceneForInteraction(*doc_.core, lastInput_, Camera{}, ground_, sceneOptions);
  // Controllers are drawn for the roles they drive, bare hands for the others.
  const bool sheetByHand = input_->sheetSource() == XrHandSource::Hand;
  const bool pointByHand = input_->pointSource() == XrHandSource::Hand;
  InputFrame controllers = lastInput_;
  if (sheetByHand) controllers.sheetHand.tracked = false;
  if (pointByHand) controllers.pointHand.tracked = false;
  desktop::addControllerModels(scene_, *doc_.core, controllers, input_->pointAim());
  const glm::vec4 handColor(0.55f, 0.5f, 0.6f, 1.0f), closedColor(0.6f, 0.3f, 0.8f, 1.0f);
  if (sheetByHand)
    desktop::addHandModel(scene_, input_->sheetJoints(),
                          doc_.core->clutched() ? closedColor : handColor);
  if (pointByHand && input_->pointJoints().tracked) {
    desktop::addHandModel(scene_, input_->pointJoints(),
                          doc_.core->twoHanded() ? closedColor : handColor);
    desktop::addPinchPoint(scene_, lastInput_.pointHand.position, input_->handInput().pinched(),
                           input_->handInput().pinchOpenness());
  }
  tracker_->describe(*doc_.core, scene_.sheet, studio_->panel().strainColours());
  scene_.light = Light{};  // fixed in the room, so both eyes see the same shading
  addStudio(scene_);
  if (lastInput_.sheetHand.tracked && studio_->creasePattern()) {
    addHeldPanel(scene_, panelCache_.panelFor(*doc_.session, scene_.colors),
                 lastInput_.sheetHand.pose, sheetHandSide(doc_.core->handedness()));
  }
}

// The panel on its card, and the ray while it points at the panel (only then).
void XrApp::addStudio(Scene& scene) {
  const std::optional<Pose>& panel = studio_->worldFromPanel();
  if (panel && studio_->drawData() && panelTexture_) {
    const glm::dvec2 half = 0.5 * studio_->placement().size;
    WorldPanel quad;
    const glm::dvec2 corners[4] = {
        {-half.x, half.y}, {half.x, half.y}, {half.x, -half.y}, {-half.x, -half.y}};
    for (int i = 0; i < 4; ++i)
      quad.corners[i] = glm::vec3(panel->apply(glm::dvec3(corners[i], 0.0)));
    scene.worldPanel = quad;
  }
  if (const std::optional<PanelRayHit> hit = studio_->ray()) {
    const glm::dvec3 from = lastInput_.pointHand.position;
    const glm::dvec3 to = from + lastInput_.pointHand.aimDirection() * hit->distance;
    const glm::vec4 rayColor{0.25f, 0.75f, 1.0f, 0.9f};
    scene.lines.push_back({glm::vec3(from), glm::vec3(to), rayColor});
    scene.markers.push_back({glm::vec3(to), 0.003f, rayColor});
  }
}

const Scene& XrApp::eyeScene(std::span<const Camera> cameras) {
  scene_.camera = cameras[0];
  scene_.secondView.reset();
  if (cameras.size() > 1) scene_.secondView = cameras[1];
  return scene_;
}

void XrApp::frame() {
  const auto now = std::chrono::steady_clock::now();
  if (lastFrame_.time_since_epoch().count() != 0)
    stats_.frameMs = std::chrono::duration<double, std::milli>(now - lastFrame_).count();
  lastFrame_ = now;
  stats_.drawnTriangles = doc_.session->current().triangleCount();
  const XrFrameTiming timing = program_->beginFrame();
  period_ = timing.period;
  if (program_->focused()) processInput(timing.displayTime);
  const bool render = timing.shouldRender && graphics_;
  if (render) buildScene();
  program_->endFrame(timing);
  if (render) ++summary_.framesRendered;
}

XrAppSummary XrApp::run(const std::atomic<bool>& interrupt) {
  try {
    return runSessions(interrupt);
  } catch (...) {
    // Every way out saves first: an error the loop did not expect still leaves the design
    // saved and the recording closed before it is reported (a session that never started
    // leaves no file).
    outputs_->finish(/*saveAlways=*/summary_.sessions > 0);
    throw;
  }
}

XrAppSummary XrApp::runSessions(const std::atomic<bool>& interrupt) {
  using namespace std::chrono_literals;
  if (!startSession())
    throw XrError("the OpenXR runtime (" + program_->runtimeName() + ") has no headset connected" +
                      kDesktopInstead,
                  XR_ERROR_FORM_FACTOR_UNAVAILABLE);
  for (;;) {
    bool exitAsked = false;
    restart_ = false;
    try {
      while (pollEvents()) {
        if (interrupt && !exitAsked) {
          summary_.interrupted = true;
          exitAsked = true;
          if (!program_->running()) break;
          program_->requestExit();
        }
        if (!program_->running()) {
          std::this_thread::sleep_for(5ms);  // the runtime has not started the session yet
          continue;
        }
        frame();
      }
    } catch (const XrError& e) {
      if (e.result() == XR_ERROR_SESSION_LOST)
        restart_ = true;
      else if (e.result() == XR_ERROR_INSTANCE_LOST)
        summary_.instanceLost = true;
      else
        throw;
    }
    // A drag in progress survives a lost session: the core holds it while the hands are
    // untracked and re-anchors them when the next session locates them.
    if (!summary_.instanceLost) {
      input_->detach();
      program_->destroySession();
    }
    if (!restart_ || summary_.instanceLost || interrupt) break;
    // LOSS_PENDING: wait for the headset to come back, then a new session.
    while (!interrupt && !startSession()) std::this_thread::sleep_for(50ms);
    if (interrupt) break;
  }
  if (!outputs_->finish(/*saveAlways=*/true)) throw FileError(outputs_->problems().back());
  for (XrSessionState state : program_->stateHistory())
    summary_.states.push_back(xrSessionStateName(state));
  summary_.folds = doc_.session->foldCount();
  if (graphics_ && graphics_->context() && graphics_->context()->validationMessageCount() > 0) {
    const std::string first = graphics_->context()->validationMessages().front();
    throw VulkanError(
        std::to_string(graphics_->context()->validationMessageCount()) +
        " Vulkan validation messages, the first: " + first.substr(0, first.find('\n')));
  }
  return summary_;
}

}  // namespace curvefold::xr
