#include "app/studio/headset_studio.hpp"

#include <imgui.h>

#include <algorithm>
#include <stdexcept>

#include "app/studio/imgui_context_scope.hpp"

namespace curvefold::studio {

namespace {

// The thumbstick scrolls this many wheel steps a second when pushed all the way.
constexpr double kScrollStepsPerSecond = 10.0;

// Dear ImGui needs a positive frame time: a frame at the same instant as the last (or earlier)
// counts as this long, far shorter than any display's frame.
constexpr double kShortestFrameSeconds = 1e-4;

// While simulating, the trigger takes the sheet's nearest point within this (metres): a hand's
// width, looser than a fold's hover (a pull need not start exactly on the paper).
constexpr double kPullReach = 0.08;

}  // namespace

HeadsetStudio::HeadsetStudio(session::Document& doc, HeadsetStudioOptions options,
                             HeadsetStudioHost host)
    : doc_(doc),
      options_(std::move(options)),
      host_(std::move(host)),
      panel_(false,
             "Ray + trigger: panel. Grip: hold the sheet; both grips: move, turn, scale. Trigger "
             "at the tip: fold (simulating: pull the paper). Panel button: show or hide this "
             "panel."),
      target_(options_.replaying, options_.suggestionSeconds, {}, options_.searchNice) {
  context_ = ImGui::CreateContext();
  ImGuiContextScope scope(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini: the layout is the code's, the same in every replay
  io.LogFilename = nullptr;
  io.DisplaySize = ImVec2(float(options_.pixels.x), float(options_.pixels.y));
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // a frame needs the atlas built
  panel_.setFillsDisplay(true);
  panel_.setRecent(options_.recent);
  nameDesign(options_.name);
  if (!options_.target.empty()) {
    target_.loadNow(options_.target, doc_);
    panel_.setTargetPath(options_.target);
  }
}

HeadsetStudio::~HeadsetStudio() {
  ImGuiContext* previous = ImGui::GetCurrentContext();
  ImGui::DestroyContext(context_);
  if (previous != context_) ImGui::SetCurrentContext(previous);
}

void HeadsetStudio::nameDesign(const std::string& name) {
  panel_.setFilesDir(options_.exportDir);  // not beside an opened design: the headset's folder
  panel_.nameDesign(name);
}

void HeadsetStudio::replace(const Design& design, const std::string& name) {
  const HandSide handedness = doc_.core->handedness();
  session::Document fresh = session::makeDocument(design, name, options_.sheetFrame, handedness);
  if (host_.documentReplacing) host_.documentReplacing(name);
  doc_.core.reset();
  doc_ = std::move(fresh);
  target_.documentReplaced();
  nameDesign(name);
  if (host_.documentReplaced) host_.documentReplaced();
}

glm::dvec3 HeadsetStudio::panelPoint(const glm::dvec2& pixel) const {
  const glm::dvec2 size = options_.placement.size;
  const glm::dvec2 uv = pixel / glm::dvec2(options_.pixels);
  return worldFromPanel_->apply({(uv.x - 0.5) * size.x, (0.5 - uv.y) * size.y, 0.0});
}

std::optional<glm::dvec3> HeadsetStudio::itemWorld(const std::string& label) const {
  if (!shown_ || !worldFromPanel_) return std::nullopt;
  const std::optional<glm::vec2> at = panel_.itemCentre(label);
  if (!at) return std::nullopt;
  return panelPoint(glm::dvec2(*at));
}

std::optional<glm::dvec3> HeadsetStudio::facing() const {
  if (!worldFromPanel_) return std::nullopt;
  return worldFromPanel_->applyToDirection({0.0, 0.0, 1.0});
}

std::optional<PanelRayHit> HeadsetStudio::ray() const {
  if (pointer_.target() != PointTarget::Panel) return std::nullopt;
  return hit_;
}

ImDrawData* HeadsetStudio::drawData() const {
  if (!shown_ || !drawn_) return nullptr;
  ImGuiContextScope scope(context_);
  return ImGui::GetDrawData();
}

void HeadsetStudio::process(InputFrame& frame, const StudioStats& measured) {
  target_.poll(doc_, frame);
  StudioStats stats = measured;
  stats.targetLine = target_.distanceLine();
  stats.suggestionLine = target_.suggestionLine(*doc_.core);
  // The panel button shows and hides the panel (on its press).
  const std::uint32_t pressed = frame.buttons & ~buttonsHeld_;
  buttonsHeld_ = frame.buttons;
  if (pressed & static_cast<std::uint32_t>(Button::Panel)) {
    shown_ = !shown_;
    pointer_.reset();
  }
  if (frame.sheetHand.tracked)
    worldFromPanel_ = frame.sheetHand.pose * options_.placement.handFromPanel;

  hit_.reset();
  const InputFrame::PointHand& point = frame.pointHand;
  if (shown_ && worldFromPanel_ && point.tracked && point.aim)
    hit_ =
        rayOnPanel(*worldFromPanel_, options_.placement.size, point.position, point.aimDirection());
  const bool dragging = doc_.core->state() == InteractionState::Dragging;
  const PointTarget target = pointer_.update(frame, shown_ ? hit_ : std::nullopt, dragging);

  pressedByPanel_ = 0;
  if (shown_) {
    ImGuiContextScope scope(context_);
    ImGuiIO& io = ImGui::GetIO();
    const double dt = std::max(frame.time - lastTime_, kShortestFrameSeconds);
    io.DeltaTime = float(dt);
    io.MousePos =
        hit_ && target == PointTarget::Panel
            ? ImVec2(float(hit_->uv.x * options_.pixels.x), float(hit_->uv.y * options_.pixels.y))
            : ImVec2(-FLT_MAX, -FLT_MAX);
    io.MouseDown[0] = pointer_.buttonDown();
    io.MouseWheel =
        target == PointTarget::Panel ? float(point.scroll * kScrollStepsPerSecond * dt) : 0.0f;
    StudioActions actions;
    actions.replaceDocument = [this](const Design& design, const std::string& name) {
      replace(design, name);
    };
    actions.press = [this](Button button) {
      pressedByPanel_ |= static_cast<std::uint32_t>(button);
    };
    actions.exportPng = [this](const std::string& path) {
      if (!host_.exportPng) throw std::runtime_error("no renderer to write " + path);
      host_.exportPng(path);
    };
    actions.foldedForm = host_.foldedForm;
    actions.resetView = [this] { doc_.core->resetView(); };
    actions.writeFile = host_.writeFile;
    actions.recentChanged = host_.recentChanged;
    actions.failed = host_.failed;
    actions.loadTarget = [this](const std::string& path) { target_.load(path, doc_); };
    actions.suggest = [this] { target_.suggest(doc_); };
    ImGui::NewFrame();
    panel_.draw(doc_, actions, stats, creasePattern_);
    ImGui::Render();
    drawn_ = true;
  }
  lastTime_ = std::max(lastTime_, frame.time);

  // The live simulation (issue 39, 4), as input for the core and the recorder: the panel's fold
  // amount, and the trigger near the simulated sheet pulling its nearest point (the sheet hand
  // holds the sheet as ever). A hidden panel keeps simulating at the amount it last had.
  frame.simulation.reset();
  if (const std::optional<double> percent = panel_.simulationPercent()) {
    SimulationInput simulation = liveSimulationInput(*percent, doc_.session->fixed());
    simulation.solver = panel_.simulationSolver();
    const InteractionThresholds& thresholds = doc_.core->thresholds();
    simulation.pull = puller_.update(point, target == PointTarget::Sheet, doc_.core->simulation(),
                                     doc_.core->worldFromSheet(), doc_.core->viewScale(),
                                     thresholds.selectPress, thresholds.selectRelease, kPullReach);
    frame.simulation = simulation;
  } else {
    puller_.reset();
  }

  // The buttons the panel pressed reach the core in this frame, as presses (a frame later they
  // are released).
  InputFrame input = frame;
  input.buttons |= pressedByPanel_;
  doc_.core->process(input, target);
}

}  // namespace curvefold::studio
