#include "interaction/interaction_core.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace curvefold {

namespace {
const std::vector<TriangleIndex> kNoTriangles;
}  // namespace

InteractionCore::InteractionCore(FoldSession& session, const Pose& worldFromSheet,
                                 HandSide handedness, const InteractionThresholds& thresholds)
    : session_(session),
      thresholds_(thresholds),
      handedness_(handedness),
      initialWorldFromSheet_(worldFromSheet),
      worldFromSheet_(worldFromSheet) {}

void InteractionCore::resetView() {
  worldFromSheet_ = initialWorldFromSheet_;
  viewScale_ = 1.0;
  clutchAnchored_ = false;  // a held clutch takes the sheet from here
  twoHanded_ = false;
  pointAnchored_ = false;
}

std::optional<ReflectionPlane> InteractionCore::plane() const {
  if (state_ == InteractionState::Dragging && session_.hasPlane()) return session_.plane();
  return std::nullopt;
}

const std::vector<TriangleIndex>& InteractionCore::reflectedTriangles() const {
  if (state_ == InteractionState::Dragging && session_.hasPlane())
    return session_.reflectedTriangles();
  return kNoTriangles;
}

const SurfacePicker& InteractionCore::picker() {
  if (!picker_ || pickerRevision_ != session_.fixedRevision()) {
    picker_ = std::make_unique<SurfacePicker>(session_.fixed());
    pickerRevision_ = session_.fixedRevision();
  }
  return *picker_;
}

const SuggestedFold* InteractionCore::offeredFold() const {
  if (offers_.empty() || state_ == InteractionState::Dragging ||
      offerRevision_ != session_.designRevision())
    return nullptr;
  return &offers_[offerIndex_];
}

bool InteractionCore::dragOffered(double time) {
  const SuggestedFold fold = offers_[offerIndex_];
  try {
    session_.beginDragAtDevelopment(fold.seed);
  } catch (const InvalidSheet&) {
    offers_.clear();
    return false;
  }
  watch_.begin(session_.fixed());
  state_ = InteractionState::Dragging;
  hover_.reset();
  emit(InteractionEventKind::Grab, time);
  dragMoved_ = true;
  session_.updateDrag(fold.to);
  watch_.update(session_.current(), session_.lastChanges(), session_.plane(), reflectedTriangles());
  lastTarget_ = fold.to;
  return true;
}

void InteractionCore::emit(InteractionEventKind kind, double time) {
  events_.push_back({kind, time});
  if (kind == InteractionEventKind::Grab || kind == InteractionEventKind::Commit)
    haptics_.push_back({HapticHand::Point, kind == InteractionEventKind::Commit ? 0.8 : 0.4,
                        kind == InteractionEventKind::Commit ? 0.04 : 0.015});
}

void InteractionCore::process(const InputFrame& frame, PointTarget target) {
  events_.clear();
  haptics_.clear();
  if (!frame.suggestions.empty()) {
    offers_ = frame.suggestions;
    offerIndex_ = 0;
    offerRevision_ = session_.designRevision();
  }
  // A trigger released in the same frame as a button press (a runtime pacing at 20 Hz sees both
  // at once) was released first: the drag commits, then the button acts (undo undoes this fold,
  // not the one before it).
  if (state_ == InteractionState::Dragging && frame.pointHand.tracked && selectHeld_ &&
      frame.pointHand.select <= thresholds_.selectRelease && (frame.buttons & ~buttonsHeld_) != 0) {
    selectHeld_ = false;
    endDrag(true, frame.time);
  }
  handleButtons(frame);
  handleSheetHand(frame);
  if (handleSimulation(frame)) {
    // The trigger pulls the simulated sheet (the host says where, in frame.simulation): it is
    // tracked so that one still held when the simulation ends does not grab.
    selectHeld_ = frame.pointHand.tracked && frame.pointHand.select >= thresholds_.selectPress;
    return;
  }
  handlePointHand(frame, target);
}

void InteractionCore::endSimulation() {
  simulation_.reset();
  simulationRevision_.reset();
  simulationProblem_.clear();
}

bool InteractionCore::handleSimulation(const InputFrame& frame) {
  if (!frame.simulation) {
    endSimulation();
    return false;
  }
  endDrag(false, frame.time);
  hover_.reset();
  const LiveSolverKind solver = frame.simulation->solver;
  if (simulationRevision_ != session_.fixedRevision() || simulationSolver_ != solver) {
    simulation_.reset();
    simulationRevision_ = session_.fixedRevision();
    simulationSolver_ = solver;
    try {
      if (solver == LiveSolverKind::Gpu && !gpuSolver_)
        throw std::runtime_error("no GPU solver here (a Vulkan device with compute)");
      simulation_ = std::make_unique<LiveSimulation>(
          // The GPU's solver shares the drawing queue: it steps in turn.
          session_.fixed(), simulationOnWorker_ && solver == LiveSolverKind::Cpu,
          solver == LiveSolverKind::Gpu ? gpuSolver_ : LiveSolverFactory{});
      simulationProblem_.clear();
    } catch (const std::exception& e) {
      simulationProblem_ = e.what();
    }
  }
  if (simulation_) simulation_->advance(*frame.simulation);
  return true;
}

void InteractionCore::endDrag(bool commit, double time) {
  if (state_ != InteractionState::Dragging) return;
  const std::size_t crossings = watch_.pairCount();
  const bool committed = commit && dragMoved_ && session_.commit();
  if (!committed) session_.cancel();
  if (committed) lastCommitIntersections_ = crossings;
  watch_.end();
  emit(committed ? InteractionEventKind::Commit : InteractionEventKind::Cancel, time);
  state_ = InteractionState::Idle;
  hover_.reset();
  quietHover_ = true;  // the tip is on the paper it just released: no hover tick for that
}

// Buttons act on presses, not on being held.
void InteractionCore::handleButtons(const InputFrame& frame) {
  const std::uint32_t pressed = frame.buttons & ~buttonsHeld_;
  buttonsHeld_ = frame.buttons;
  auto wasPressed = [&](Button b) { return (pressed & static_cast<std::uint32_t>(b)) != 0; };

  if (wasPressed(Button::SwitchHands)) {
    // The hands trade roles: whatever either was doing ends, and the sheet stays where it is.
    endDrag(false, frame.time);
    clutched_ = false;
    selectHeld_ = false;
    hover_.reset();
    handedness_ = otherHand(handedness_);
    emit(InteractionEventKind::SwitchHands, frame.time);
  }
  if (wasPressed(Button::Cancel)) endDrag(false, frame.time);
  if (wasPressed(Button::Undo)) {
    endDrag(false, frame.time);
    if (session_.undo()) {
      lastCommitIntersections_ = 0;  // about a fold no longer last
      emit(InteractionEventKind::Undo, frame.time);
    }
  }
  if (wasPressed(Button::Redo)) {
    endDrag(false, frame.time);
    if (session_.redo()) {
      lastCommitIntersections_ = 0;
      emit(InteractionEventKind::Redo, frame.time);
    }
  }
  if (wasPressed(Button::NextSuggestion) && offeredFold())
    offerIndex_ = (offerIndex_ + 1) % offers_.size();
  if (wasPressed(Button::TakeSuggestion)) {
    endDrag(false, frame.time);
    if (offeredFold() && dragOffered(frame.time)) {
      // The hand's trigger has nothing to do with this fold: a later release must not end it.
      pointAnchored_ = false;
      endDrag(true, frame.time);
    }
  }
}

namespace {

// The shortest rotation taking unit vector u to unit vector v (any half turn when opposite).
glm::dquat rotationBetween(const glm::dvec3& u, const glm::dvec3& v) {
  const double cosine = glm::dot(u, v);
  if (cosine < -1.0 + 1e-12) {
    glm::dvec3 axis = glm::cross(glm::dvec3(1, 0, 0), u);
    if (glm::dot(axis, axis) < 1e-12) axis = glm::cross(glm::dvec3(0, 1, 0), u);
    return glm::angleAxis(std::numbers::pi, glm::normalize(axis));
  }
  const glm::dvec3 axis = glm::cross(u, v);
  return glm::normalize(glm::dquat(1.0 + cosine, axis.x, axis.y, axis.z));
}

}  // namespace

// The sheet between two hands: the segment from the sheet hand to the point hand at the start
// maps onto the segment now (its midpoint, direction and length), and the sheet with it.
bool InteractionCore::handleTwoHands(const InputFrame& frame) {
  const InputFrame::PointHand& point = frame.pointHand;
  if (gripHeld_ && point.grip <= thresholds_.clutchRelease) gripHeld_ = false;
  if (!gripHeld_ && point.grip >= thresholds_.clutchPress) gripHeld_ = true;
  // The trigger released: on a controller whose squeeze is its trigger (khr/simple_controller)
  // both read the same, and that is a grab, not two hands.
  const bool holding =
      clutched_ && gripHeld_ && !selectHeld_ && point.select < thresholds_.selectPress &&
      state_ != InteractionState::Dragging && frame.sheetHand.tracked && point.tracked;
  if (!holding) {
    if (twoHanded_) {
      twoHanded_ = false;
      clutchAnchored_ = false;  // one hand goes on from where the two left the sheet
    }
    return false;
  }
  const glm::dvec3 a = frame.sheetHand.pose.position, b = point.position;
  if (!twoHanded_) {
    twoHanded_ = true;
    sheetHandAtTwoHands_ = a;
    pointHandAtTwoHands_ = b;
    sheetAtTwoHands_ = worldFromSheet_;
    scaleAtTwoHands_ = viewScale_;
    hover_.reset();
  }
  const glm::dvec3 from = pointHandAtTwoHands_ - sheetHandAtTwoHands_, to = b - a;
  const double spanFrom = glm::length(from), spanTo = glm::length(to);
  if (spanFrom < thresholds_.minimumHandSpan || spanTo < thresholds_.minimumHandSpan) return true;
  const double scale = std::clamp(scaleAtTwoHands_ * spanTo / spanFrom,
                                  thresholds_.minimumViewScale, thresholds_.maximumViewScale);
  const double factor = scale / scaleAtTwoHands_;
  const glm::dquat turn = rotationBetween(from / spanFrom, to / spanTo);
  const glm::dvec3 midFrom = 0.5 * (sheetHandAtTwoHands_ + pointHandAtTwoHands_);
  const glm::dvec3 midTo = 0.5 * (a + b);
  // world' = midTo + factor * turn * (world - midFrom), applied to world = pose(scale * x).
  worldFromSheet_.position = midTo + factor * (turn * (sheetAtTwoHands_.position - midFrom));
  worldFromSheet_.orientation = glm::normalize(turn * sheetAtTwoHands_.orientation);
  viewScale_ = scale;
  return true;
}

// world_from_sheet = hand_now * inverse(hand_at_clutch) * world_from_sheet_at_clutch.
void InteractionCore::handleSheetHand(const InputFrame& frame) {
  const InputFrame::SheetHand& hand = frame.sheetHand;
  if (clutched_ && hand.clutch <= thresholds_.clutchRelease && hand.tracked) clutched_ = false;
  if (!clutched_ && hand.tracked && hand.clutch >= thresholds_.clutchPress) {
    clutched_ = true;
    clutchAnchored_ = false;
  }
  if (handleTwoHands(frame) || !clutched_) return;
  // A lost hand freezes the sheet; when it comes back the clutch re-anchors there, so the sheet
  // never jumps to where the hand reappeared.
  if (!hand.tracked) {
    clutchAnchored_ = false;
    return;
  }
  if (!clutchAnchored_) {
    handAtClutch_ = hand.pose;
    sheetAtClutch_ = worldFromSheet_;
    clutchAnchored_ = true;
  }
  worldFromSheet_ = hand.pose * handAtClutch_.inverse() * sheetAtClutch_;
}

void InteractionCore::handlePointHand(const InputFrame& frame, PointTarget target) {
  const InputFrame::PointHand& hand = frame.pointHand;
  if (!hand.tracked) {
    // Nothing is known about the point: keep the drag as it is and re-anchor when it returns.
    hover_.reset();
    pointAnchored_ = false;
    if (state_ == InteractionState::Hover) state_ = InteractionState::Idle;
    return;
  }
  // Trigger hysteresis.
  const bool wasHeld = selectHeld_;
  if (selectHeld_ && hand.select <= thresholds_.selectRelease) selectHeld_ = false;
  if (!selectHeld_ && hand.select >= thresholds_.selectPress) selectHeld_ = true;
  const glm::dvec3 tip = sheetOf(hand.position);

  if (state_ == InteractionState::Dragging) {
    if (!selectHeld_) {
      endDrag(true, frame.time);
      return;
    }
    if (!pointAnchored_) {
      grabOffset_ = lastTarget_ - tip;
      pointAnchored_ = true;
    }
    const glm::dvec3 target = tip + grabOffset_;
    // A tracking glitch far out of reach (or NaN) moves nothing: the drag waits where it was.
    if (!withinReach(target, session_.grabbedPoint(), session_.epsilon() / kRelativeEpsilon))
      return;
    if (!dragMoved_ && glm::distance(target, session_.grabbedPoint()) >=
                           thresholds_.minimumDragDistance / viewScale_)
      dragMoved_ = true;
    if (dragMoved_ && target != lastTarget_) {
      session_.updateDrag(target);
      const std::size_t before = watch_.pairCount();
      watch_.update(session_.current(), session_.lastChanges(), session_.plane(),
                    reflectedTriangles());
      // A short pulse as the fold starts to pass through the sheet.
      if (before == 0 && watch_.pairCount() > 0) haptics_.push_back(kIntersectionPulse);
    }
    lastTarget_ = target;
    return;
  }

  const bool wasHovering = hover_.has_value();
  hover_.reset();
  if (target == PointTarget::Panel) {
    // The trigger's state is kept, so a press that began on the panel grabs nothing after it.
    quietHover_ = false;
    state_ = InteractionState::Idle;
    return;
  }
  // The hover radius is the hand's (world metres); the sheet is seen at the view scale.
  if (const std::optional<SurfacePoint> nearest =
          twoHanded_ ? std::nullopt : picker().nearest(tip, thresholds_.hoverRadius / viewScale_)) {
    const glm::dvec3 position = positionOf(session_.fixed(), *nearest);
    hover_ = HoverPoint{*nearest, position, viewScale_ * glm::distance(position, tip)};
  }
  // A faint tick as the tip comes within reach of the paper (not as a drag ends over it: the
  // commit's pulse says enough).
  if (hover_ && !wasHovering && !quietHover_) haptics_.push_back(kHoverEnterPulse);
  quietHover_ = false;
  state_ = hover_ ? InteractionState::Hover : InteractionState::Idle;

  // A grab needs a fresh press while hovering: sweeping a held trigger onto the sheet grabs
  // nothing.
  if (hover_ && selectHeld_ && !wasHeld) {
    // A grab at the offered fold's point takes the fold as suggested, to adjust from there.
    if (const SuggestedFold* offer = offeredFold();
        offer && viewScale_ * glm::distance(offer->grab, tip) <= thresholds_.hoverRadius &&
        dragOffered(frame.time)) {
      grabOffset_ = lastTarget_ - tip;
      pointAnchored_ = true;
      return;
    }
    const glm::dvec3 grabbed = session_.beginDrag(hover_->point);
    watch_.begin(session_.fixed());
    grabOffset_ = grabbed - tip;  // keeps the tip-to-point offset: nothing jumps
    lastTarget_ = grabbed;
    pointAnchored_ = true;
    dragMoved_ = false;
    state_ = InteractionState::Dragging;
    hover_.reset();
    emit(InteractionEventKind::Grab, frame.time);
  }
}

}  // namespace curvefold
