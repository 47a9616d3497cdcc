#include "interaction/interaction_core.hpp"

#include <glm/geometric.hpp>

namespace curvefold {

namespace {
const std::vector<TriangleIndex> kNoTriangles;
}  // namespace

InteractionCore::InteractionCore(FoldSession& session, const Pose& worldFromSheet,
                                 Handedness handedness, const InteractionThresholds& thresholds)
    : session_(session),
      thresholds_(thresholds),
      handedness_(handedness),
      worldFromSheet_(worldFromSheet) {}

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

void InteractionCore::emit(InteractionEventKind kind, double time) {
  events_.push_back({kind, time});
  if (kind == InteractionEventKind::Grab || kind == InteractionEventKind::Commit)
    haptics_.push_back({HapticHand::Point, kind == InteractionEventKind::Commit ? 0.8 : 0.4,
                        kind == InteractionEventKind::Commit ? 0.04 : 0.015});
}

void InteractionCore::process(const InputFrame& frame) {
  events_.clear();
  haptics_.clear();
  // A trigger released in the same frame as a button press (a runtime pacing at 20 Hz sees both
  // at once) was released first: the drag commits, then the button acts (undo undoes this fold,
  // not the one before it).
  if (state_ == InteractionState::Dragging && frame.pointHand.tracked && selectHeld_ &&
      frame.pointHand.select <= thresholds_.selectRelease && (frame.buttons & ~buttonsHeld_) != 0) {
    selectHeld_ = false;
    endDrag(true, frame.time);
  }
  handleButtons(frame);
  handleSheetHand(frame.sheetHand);
  handlePointHand(frame);
}

void InteractionCore::endDrag(bool commit, double time) {
  if (state_ != InteractionState::Dragging) return;
  const bool committed = commit && dragMoved_ && session_.commit();
  if (!committed) session_.cancel();
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
    handedness_ = handedness_ == Handedness::Right ? Handedness::Left : Handedness::Right;
    emit(InteractionEventKind::SwitchHands, frame.time);
  }
  if (wasPressed(Button::Cancel)) endDrag(false, frame.time);
  if (wasPressed(Button::Undo)) {
    endDrag(false, frame.time);
    if (session_.undo()) emit(InteractionEventKind::Undo, frame.time);
  }
  if (wasPressed(Button::Redo)) {
    endDrag(false, frame.time);
    if (session_.redo()) emit(InteractionEventKind::Redo, frame.time);
  }
}

// world_from_sheet = hand_now * inverse(hand_at_clutch) * world_from_sheet_at_clutch.
void InteractionCore::handleSheetHand(const InputFrame::SheetHand& hand) {
  if (clutched_ && hand.clutch <= thresholds_.clutchRelease && hand.tracked) clutched_ = false;
  if (!clutched_) {
    if (hand.tracked && hand.clutch >= thresholds_.clutchPress) {
      clutched_ = true;
      clutchAnchored_ = false;
    } else {
      return;
    }
  }
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

void InteractionCore::handlePointHand(const InputFrame& frame) {
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
  const glm::dvec3 tip = worldFromSheet_.inverse().apply(hand.position);

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
    if (!dragMoved_ &&
        glm::distance(target, session_.grabbedPoint()) >= thresholds_.minimumDragDistance)
      dragMoved_ = true;
    if (dragMoved_ && target != lastTarget_) session_.updateDrag(target);
    lastTarget_ = target;
    return;
  }

  const bool wasHovering = hover_.has_value();
  hover_.reset();
  if (const std::optional<SurfacePoint> nearest = picker().nearest(tip, thresholds_.hoverRadius)) {
    const glm::dvec3 position = positionOf(session_.fixed(), *nearest);
    hover_ = HoverPoint{*nearest, position, glm::distance(position, tip)};
  }
  // A faint tick as the tip comes within reach of the paper (not as a drag ends over it: the
  // commit's pulse says enough).
  if (hover_ && !wasHovering && !quietHover_) haptics_.push_back(kHoverEnterPulse);
  quietHover_ = false;
  state_ = hover_ ? InteractionState::Hover : InteractionState::Idle;

  // A grab needs a fresh press while hovering: sweeping a held trigger onto the sheet grabs
  // nothing.
  if (hover_ && selectHeld_ && !wasHeld) {
    const glm::dvec3 grabbed = session_.beginDrag(hover_->point);
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
