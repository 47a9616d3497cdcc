// Each interaction rule of docs/design.md 5, driven by synthetic frames on a flat square sheet
// (z = 0, centred on the origin, front +z).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/surfaces/surfaces.hpp"
#include "interaction/interaction_core.hpp"
#include "interaction/panel_pointer.hpp"
#include "sheet_fixtures.hpp"

namespace curvefold {
namespace {

using testing::expectInvariants;

Sheet square() {
  // 0.2 m square centred on the origin, 10 x 10 cells.
  Sheet sheet = testing::flatGrid(10, 10, 0.02);
  for (glm::dvec3& p : sheet.positions) p -= glm::dvec3(0.1, 0.1, 0.0);
  for (glm::dvec2& q : sheet.development) q -= glm::dvec2(0.1, 0.1);
  return sheet;
}

glm::dquat rotation(double degrees, const glm::dvec3& axis) {
  return glm::angleAxis(degrees * std::numbers::pi / 180.0, glm::normalize(axis));
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// A session on the square held at a pose in front of the user, and a way to send frames.
class Interaction : public ::testing::Test {
 protected:
  Interaction() : session_(square()), core_(session_, sheetFrame_) {
    frame_.sheetHand.pose = {{-0.2, 1.0, -0.3}, glm::dquat(1, 0, 0, 0)};
    frame_.sheetHand.tracked = true;
    frame_.pointHand.position = {0.3, 1.2, -0.3};
    frame_.pointHand.tracked = true;
  }

  // Sends the current frame, advanced by one 90 Hz tick, and checks the displayed sheet.
  void send() {
    frame_.time += 1.0 / 90.0;
    core_.process(frame_);
    expectInvariants(session_.current(), session_.initial());
  }
  // The world position of a sheet point under the current sheet frame.
  glm::dvec3 world(const glm::dvec3& sheetPoint) const { return core_.worldOf(sheetPoint); }
  void pointAt(const glm::dvec3& worldPosition, double select) {
    frame_.pointHand.position = worldPosition;
    frame_.pointHand.select = select;
    send();
  }
  bool sawEvent(InteractionEventKind kind) const {
    for (const InteractionEvent& e : core_.events())
      if (e.kind == kind) return true;
    return false;
  }
  // Grab the world point `start` on the sheet and drag it by `by` in steps, trigger held.
  void dragBy(const glm::dvec3& start, const glm::dvec3& by) {
    pointAt(start, 0.0);
    pointAt(start, 1.0);
    for (int i = 1; i <= 5; ++i) pointAt(start + by * (i / 5.0), 1.0);
  }
  // Grab the sheet point p, drag it by `by` (world) in steps, release.
  void fold(const glm::dvec3& p, const glm::dvec3& by) {
    dragBy(world(p), by);
    pointAt(world(p) + by, 0.0);
  }

  const Pose sheetFrame_{{0.0, 1.2, -0.4}, rotation(30, {1, 0, 0})};
  FoldSession session_;
  InteractionCore core_;
  InputFrame frame_;
};

TEST_F(Interaction, ClutchMovesTheSheetRigidly) {
  const Pose handA = frame_.sheetHand.pose;
  frame_.sheetHand.clutch = 1.0;
  send();
  EXPECT_TRUE(core_.clutched());
  const Pose handB{{0.1, 1.3, -0.2}, rotation(40, {0, 1, 1})};
  frame_.sheetHand.pose = handB;
  send();
  const Pose expected = handB * handA.inverse() * sheetFrame_;
  expectNear(core_.worldFromSheet().position, expected.position);
  EXPECT_NEAR(glm::dot(core_.worldFromSheet().orientation, expected.orientation), 1.0, 1e-12);
  // Rigid: the sheet itself (in sheet coordinates) did not change, and distances are kept.
  EXPECT_TRUE(identical(session_.current(), session_.initial()));
  const glm::dvec3 a{0.1, 0.0, 0.0}, b{-0.05, 0.07, 0.0};
  EXPECT_NEAR(glm::distance(world(a), world(b)), glm::distance(a, b), 1e-12);
  // Release: the hand moves on without the sheet.
  frame_.sheetHand.clutch = 0.0;
  send();
  const Pose held = core_.worldFromSheet();
  frame_.sheetHand.pose = {{0.5, 0.5, 0.5}, rotation(90, {0, 0, 1})};
  send();
  EXPECT_EQ(core_.worldFromSheet(), held);
}

// Issue 14, 2: with both squeezes held the sheet moves, turns and scales between the hands (a
// view scale: the design stays in metres); letting one go hands the sheet to the other without a
// jump; folding at scale 2 takes the tip's motion at half in sheet metres; reset puts it back.
TEST_F(Interaction, TwoHandsMoveTurnAndScaleTheSheet) {
  const glm::dvec3 a0 = frame_.sheetHand.pose.position;
  frame_.pointHand.position = a0 + glm::dvec3(0.3, 0.0, 0.0);
  const glm::dvec3 b0 = frame_.pointHand.position;
  const glm::dvec3 corner{0.1, 0.1, 0.0};  // a sheet point
  const glm::dvec3 before = world(corner);
  frame_.sheetHand.clutch = 1.0;
  frame_.pointHand.grip = 1.0;
  send();
  ASSERT_TRUE(core_.twoHanded());
  EXPECT_EQ(core_.viewScale(), 1.0);
  expectNear(world(corner), before);  // taking hold moves nothing
  // The point hand swings a quarter turn about the vertical and the span doubles: the world is
  // turned and doubled about the hands' midpoint.
  const glm::dquat quarter = rotation(90, {0, 1, 0});
  const glm::dvec3 a1 = a0 + glm::dvec3(0.0, 0.05, 0.0);
  const glm::dvec3 b1 = a1 + quarter * ((b0 - a0) * 2.0);
  frame_.sheetHand.pose.position = a1;
  frame_.pointHand.position = b1;
  send();
  EXPECT_NEAR(core_.viewScale(), 2.0, 1e-12);
  const glm::dvec3 expected = 0.5 * (a1 + b1) + 2.0 * (quarter * (before - 0.5 * (a0 + b0)));
  {
    SCOPED_TRACE("turned and doubled");
    expectNear(world(corner), expected);
  }
  EXPECT_TRUE(identical(session_.current(), session_.initial()));  // the design is untouched
  // Hands pulled far apart: the scale stops at the maximum.
  frame_.pointHand.position = a1 + quarter * ((b0 - a0) * 100.0);
  send();
  EXPECT_EQ(core_.viewScale(), core_.thresholds().maximumViewScale);
  frame_.pointHand.position = b1;
  send();
  // Letting go of the point hand's squeeze: the sheet hand alone holds it from there.
  frame_.pointHand.grip = 0.0;
  send();
  EXPECT_FALSE(core_.twoHanded());
  const glm::dvec3 held = world(corner);
  {
    SCOPED_TRACE("one hand takes over");
    expectNear(held, expected);
  }
  frame_.sheetHand.pose.position += glm::dvec3(0.0, 0.0, 0.1);
  send();
  expectNear(world(corner), held + glm::dvec3(0.0, 0.0, 0.1));
  frame_.sheetHand.clutch = 0.0;
  send();
  // A fold at scale 2: the tip moves 4 cm (world), the grabbed point 2 cm (sheet metres).
  const glm::dvec3 onSheet{0.05, 0.05, 0.0};
  pointAt(world(onSheet), 0.0);
  pointAt(world(onSheet), 1.0);
  ASSERT_EQ(core_.state(), InteractionState::Dragging);
  const glm::dvec3 up = core_.worldFromSheet().applyToDirection({0.0, 0.0, 1.0});
  pointAt(world(onSheet) + 0.04 * up, 1.0);
  EXPECT_NEAR(glm::distance(core_.grabTarget(), core_.grabStart()), 0.02, 1e-9);
  pointAt(frame_.pointHand.position, 0.0);
  EXPECT_EQ(session_.foldCount(), 1u);
  // A squeeze that is also the trigger (khr/simple_controller: both read select/click) grabs in
  // the frame it is pulled, never takes two hands, even with the sheet clutched.
  pointAt(world(session_.fixed().positions[0]), 0.0);  // a vertex: on the sheet, folded or not
  ASSERT_EQ(core_.state(), InteractionState::Hover);
  frame_.sheetHand.clutch = 1.0;
  frame_.pointHand.grip = 1.0;
  frame_.pointHand.select = 1.0;
  send();
  EXPECT_EQ(core_.state(), InteractionState::Dragging);
  send();
  EXPECT_FALSE(core_.twoHanded());
  frame_.sheetHand.clutch = frame_.pointHand.grip = frame_.pointHand.select = 0.0;
  send();
  core_.resetView();
  EXPECT_EQ(core_.viewScale(), 1.0);
  EXPECT_EQ(core_.worldFromSheet(), sheetFrame_);
}

TEST_F(Interaction, HoverPicksTheNearestPointWithinTheRadius) {
  const glm::dvec3 onSheet{0.031, -0.047, 0.0};
  pointAt(world(onSheet + glm::dvec3(0, 0, 0.01)), 0.0);  // 1 cm above the paper
  ASSERT_TRUE(core_.hover().has_value());
  EXPECT_EQ(core_.state(), InteractionState::Hover);
  expectNear(core_.hover()->sheetPosition, onSheet);
  EXPECT_NEAR(core_.hover()->distance, 0.01, 1e-12);
  pointAt(world(onSheet + glm::dvec3(0, 0, core_.thresholds().hoverRadius + 0.001)), 0.0);
  EXPECT_FALSE(core_.hover().has_value());
  EXPECT_EQ(core_.state(), InteractionState::Idle);
  // Pulling the trigger out of range grabs nothing.
  pointAt(frame_.pointHand.position, 1.0);
  EXPECT_EQ(core_.state(), InteractionState::Idle);
}

// Issue 14, 3: a faint pulse as the tip comes within reach of the paper, once per entry; none
// while it stays, none as a drag ends over the paper (the commit pulses), one again on re-entry.
TEST_F(Interaction, EnteringHoverPulsesOnce) {
  const glm::dvec3 onSheet{0.031, -0.047, 0.0};
  auto pulses = [&] { return core_.haptics().size(); };
  pointAt(world(onSheet + glm::dvec3(0, 0, 0.01)), 0.0);
  ASSERT_EQ(pulses(), 1u);
  EXPECT_EQ(core_.haptics()[0].amplitude, kHoverEnterPulse.amplitude);
  pointAt(world(onSheet + glm::dvec3(0, 0, 0.008)), 0.0);
  EXPECT_EQ(pulses(), 0u);
  pointAt(world(onSheet + glm::dvec3(0, 0, 0.2)), 0.0);  // away
  EXPECT_EQ(pulses(), 0u);
  pointAt(world(onSheet + glm::dvec3(0, 0, 0.01)), 0.0);  // back
  EXPECT_EQ(pulses(), 1u);
  fold({0.08, 0.08, 0.0}, {0.0, 0.0, 0.05});  // ends with a release over the paper
  ASSERT_TRUE(sawEvent(InteractionEventKind::Commit));
  EXPECT_EQ(pulses(), 1u);  // the commit's alone
  EXPECT_GT(core_.haptics()[0].amplitude, kHoverEnterPulse.amplitude);
  pointAt(frame_.pointHand.position, 0.0);
  EXPECT_EQ(pulses(), 0u);
}

TEST_F(Interaction, TargetFollowsTheTipWithTheGrabOffset) {
  const glm::dvec3 onSheet{0.08, 0.08, 0.0};
  const glm::dvec3 above = onSheet + glm::dvec3(0, 0, 0.012);
  pointAt(world(above), 0.0);
  pointAt(world(above), 1.0);
  ASSERT_EQ(core_.state(), InteractionState::Dragging);
  EXPECT_TRUE(sawEvent(InteractionEventKind::Grab));
  ASSERT_EQ(core_.haptics().size(), 1u);
  const glm::dvec3 offset = core_.grabStart() - above;
  expectNear(core_.grabStart(), onSheet);
  const glm::dvec3 tip = world(above) + glm::dvec3(-0.03, 0.02, 0.05);
  pointAt(tip, 1.0);
  expectNear(core_.grabTarget(), core_.worldFromSheet().inverse().apply(tip) + offset);
  ASSERT_TRUE(core_.plane().has_value());
  EXPECT_FALSE(core_.reflectedTriangles().empty());
}

TEST_F(Interaction, ReleaseCommitsAndCancelRestores) {
  fold({0.1, 0.1, 0.0}, {-0.02, -0.03, 0.06});
  EXPECT_TRUE(sawEvent(InteractionEventKind::Commit));
  EXPECT_EQ(session_.foldCount(), 1u);
  EXPECT_EQ(core_.state(), InteractionState::Idle);
  const Sheet afterOne = session_.fixed();

  // A second drag, cancelled with the button mid-way: the fixed sheet comes back bit for bit.
  const glm::dvec3 corner = world({-0.1, -0.1, 0.0});
  pointAt(corner, 0.0);
  pointAt(corner, 1.0);
  pointAt(corner + glm::dvec3(0.02, 0.03, 0.05), 1.0);
  EXPECT_FALSE(identical(session_.current(), afterOne));
  frame_.buttons = static_cast<std::uint32_t>(Button::Cancel);
  send();
  EXPECT_TRUE(sawEvent(InteractionEventKind::Cancel));
  EXPECT_TRUE(identical(session_.current(), afterOne));
  frame_.buttons = 0;
  pointAt(corner, 0.0);  // releasing after a cancel commits nothing
  EXPECT_EQ(session_.foldCount(), 1u);
}

TEST_F(Interaction, MovingOnlyTheSheetHandDuringADragChangesTheFold) {
  const glm::dvec3 corner = world({0.1, -0.1, 0.0});
  pointAt(corner, 0.0);
  pointAt(corner, 1.0);
  const glm::dvec3 tip = corner + glm::dvec3(-0.03, 0.02, 0.06);
  pointAt(tip, 1.0);
  const Sheet before = session_.current();
  const glm::dvec3 targetBefore = core_.grabTarget();
  const glm::dvec3 offset = targetBefore - core_.worldFromSheet().inverse().apply(tip);
  // The tip stays; the non-dominant hand clutches and turns the sheet.
  frame_.sheetHand.clutch = 1.0;
  send();
  frame_.sheetHand.pose.orientation = rotation(25, {0, 1, 0});
  frame_.sheetHand.pose.position += glm::dvec3(0.02, 0.0, 0.0);
  send();
  EXPECT_NE(core_.grabTarget(), targetBefore);
  expectNear(core_.grabTarget(), core_.worldFromSheet().inverse().apply(tip) + offset);
  EXPECT_FALSE(identical(session_.current(), before));
  pointAt(tip, 0.0);
  EXPECT_EQ(session_.foldCount(), 1u);
}

TEST_F(Interaction, UndoAndRedoButtons) {
  fold({0.1, 0.1, 0.0}, {-0.02, -0.03, 0.06});
  fold({-0.1, 0.1, 0.0}, {0.03, -0.02, 0.05});
  ASSERT_EQ(session_.foldCount(), 2u);
  const Sheet afterTwo = session_.fixed();
  frame_.buttons = static_cast<std::uint32_t>(Button::Undo);
  send();
  EXPECT_TRUE(sawEvent(InteractionEventKind::Undo));
  send();  // held, not pressed again: one undo only
  EXPECT_EQ(session_.foldCount(), 1u);
  frame_.buttons = static_cast<std::uint32_t>(Button::Redo);
  send();
  EXPECT_TRUE(sawEvent(InteractionEventKind::Redo));
  EXPECT_TRUE(identical(session_.fixed(), afterTwo));
}

// Issue 13, C13: a trigger release and an undo press in the same frame (a runtime pacing at 20 Hz)
// cancelled the drag and undid the fold before it. The release comes first: commit, then undo.
TEST_F(Interaction, ReleaseAndUndoInOneFrameCommitThenUndo) {
  fold({0.1, 0.1, 0.0}, {-0.02, -0.03, 0.06});
  ASSERT_EQ(session_.foldCount(), 1u);
  const Sheet afterOne = session_.fixed();
  const glm::dvec3 start = world({-0.1, 0.1, 0.0});
  dragBy(start, {0.03, -0.02, 0.05});
  frame_.buttons = static_cast<std::uint32_t>(Button::Undo);
  pointAt(start + glm::dvec3(0.03, -0.02, 0.05), 0.0);  // release and undo together
  EXPECT_TRUE(sawEvent(InteractionEventKind::Commit));
  EXPECT_TRUE(sawEvent(InteractionEventKind::Undo));
  EXPECT_FALSE(sawEvent(InteractionEventKind::Cancel));
  EXPECT_EQ(session_.foldCount(), 1u);  // the second fold committed, then undone
  EXPECT_TRUE(session_.canRedo());
  EXPECT_TRUE(identical(session_.fixed(), afterOne));
  // A button pressed while the trigger is still held cancels the drag, as before.
  frame_.buttons = 0;
  dragBy(start, {0.03, -0.02, 0.05});
  frame_.buttons = static_cast<std::uint32_t>(Button::Cancel);
  pointAt(start + glm::dvec3(0.03, -0.02, 0.05), 1.0);
  EXPECT_TRUE(sawEvent(InteractionEventKind::Cancel));
  EXPECT_EQ(session_.foldCount(), 1u);
}

// Issue 13, A3 in a live session: a tracking glitch that puts the point hand absurdly far away
// during a drag moves nothing (and throws nothing); the drag goes on from where it was.
TEST_F(Interaction, AHandGlitchFarOutOfReachMovesNothing) {
  const glm::dvec3 start = world({0.1, 0.1, 0.0});
  dragBy(start, {-0.02, -0.03, 0.06});
  const Sheet before = session_.current();
  EXPECT_NO_THROW(pointAt({1e300, 0.0, 0.0}, 1.0));
  EXPECT_EQ(core_.state(), InteractionState::Dragging);
  EXPECT_TRUE(identical(session_.current(), before));
  pointAt(start + glm::dvec3(-0.02, -0.03, 0.06), 0.0);
  EXPECT_TRUE(sawEvent(InteractionEventKind::Commit));
  EXPECT_EQ(session_.foldCount(), 1u);
}

TEST_F(Interaction, SwitchingHandsEndsTheDragAndSwapsRoles) {
  const glm::dvec3 corner = world({0.1, 0.1, 0.0});
  pointAt(corner, 0.0);
  pointAt(corner, 1.0);
  pointAt(corner + glm::dvec3(-0.02, -0.02, 0.05), 1.0);
  ASSERT_EQ(core_.state(), InteractionState::Dragging);
  frame_.sheetHand.clutch = 1.0;
  frame_.buttons = static_cast<std::uint32_t>(Button::SwitchHands);
  send();
  EXPECT_EQ(core_.handedness(), HandSide::Left);
  EXPECT_TRUE(sawEvent(InteractionEventKind::SwitchHands));
  EXPECT_NE(core_.state(), InteractionState::Dragging);
  EXPECT_EQ(session_.foldCount(), 0u);
  EXPECT_TRUE(identical(session_.current(), session_.initial()));
  // The trigger still held from before the switch does not grab: it needs a new press.
  frame_.buttons = 0;
  pointAt(corner, 1.0);
  EXPECT_NE(core_.state(), InteractionState::Dragging);
  pointAt(corner, 0.0);
  pointAt(corner, 1.0);
  EXPECT_EQ(core_.state(), InteractionState::Dragging);
}

TEST_F(Interaction, UntrackedHandsAreIgnoredNotJumpedTo) {
  frame_.sheetHand.clutch = 1.0;
  send();
  frame_.sheetHand.pose.position += glm::dvec3(0.05, 0, 0);
  send();
  const Pose beforeLoss = core_.worldFromSheet();
  // The sheet hand is lost and reappears 30 cm away: the sheet stays, then follows relative motion.
  frame_.sheetHand.tracked = false;
  frame_.sheetHand.pose.position += glm::dvec3(0.3, 0, 0);
  send();
  EXPECT_EQ(core_.worldFromSheet(), beforeLoss);
  frame_.sheetHand.tracked = true;
  send();
  expectNear(core_.worldFromSheet().position, beforeLoss.position);
  frame_.sheetHand.pose.position += glm::dvec3(0.0, 0.01, 0);
  send();
  expectNear(core_.worldFromSheet().position, beforeLoss.position + glm::dvec3(0.0, 0.01, 0));
  frame_.sheetHand.clutch = 0.0;
  send();

  // The point hand is lost mid-drag and returns elsewhere: the target continues from where it was.
  const glm::dvec3 corner = world({0.1, 0.1, 0.0});
  pointAt(corner, 0.0);
  pointAt(corner, 1.0);
  pointAt(corner + glm::dvec3(-0.02, 0, 0.03), 1.0);
  const glm::dvec3 target = core_.grabTarget();
  frame_.pointHand.tracked = false;
  pointAt(corner + glm::dvec3(0.4, 0.4, 0.4), 0.0);  // garbage while untracked
  EXPECT_EQ(core_.state(), InteractionState::Dragging);
  EXPECT_EQ(core_.grabTarget(), target);
  frame_.pointHand.tracked = true;
  pointAt(corner + glm::dvec3(0.4, 0.4, 0.4), 1.0);
  expectNear(core_.grabTarget(), target);
  pointAt(corner + glm::dvec3(0.4, 0.4, 0.41), 1.0);
  expectNear(core_.grabTarget(),
             target + core_.worldFromSheet().inverse().applyToDirection({0, 0, 0.01}));
}

TEST_F(Interaction, NoisyTriggerDoesNotStartOrStopDrags) {
  const glm::dvec3 corner = world({0.1, 0.1, 0.0});
  // Hovering near the press threshold without reaching it: no grab.
  for (double select : {0.7, 0.74, 0.7, 0.745, 0.6}) {
    pointAt(corner, select);
    EXPECT_NE(core_.state(), InteractionState::Dragging) << select;
  }
  pointAt(corner, 0.8);
  ASSERT_EQ(core_.state(), InteractionState::Dragging);
  // Noise around the middle and near the release threshold keeps the drag.
  const glm::dvec3 tip = corner + glm::dvec3(-0.02, -0.03, 0.05);
  for (double select : {0.5, 0.3, 0.6, 0.26, 0.5, 0.3}) {
    pointAt(tip, select);
    EXPECT_EQ(core_.state(), InteractionState::Dragging) << select;
  }
  pointAt(tip, 0.2);
  EXPECT_TRUE(sawEvent(InteractionEventKind::Commit));
  EXPECT_EQ(session_.foldCount(), 1u);
}

TEST_F(Interaction, AClickWithoutMotionAddsNoFold) {
  const glm::dvec3 p = world({0.02, 0.03, 0.0});
  pointAt(p, 0.0);
  pointAt(p, 1.0);
  pointAt(p + glm::dvec3(0.0005, 0, 0), 1.0);  // under the minimum drag distance
  EXPECT_FALSE(core_.plane().has_value());
  pointAt(p, 0.0);
  EXPECT_TRUE(sawEvent(InteractionEventKind::Cancel));
  EXPECT_EQ(session_.foldCount(), 0u);
  EXPECT_TRUE(identical(session_.fixed(), session_.initial()));
}

// Issue 14, 1: while the ray is on the panel the tip neither hovers nor grabs; a press that
// began there grabs nothing when the tip then reaches the paper; a drag under way goes on.
TEST_F(Interaction, OnThePanelTheTipDoesNotGrab) {
  const glm::dvec3 p = world({0.02, 0.03, 0.0});
  frame_.pointHand.position = p;
  frame_.time += 1.0 / 90.0;
  core_.process(frame_, PointTarget::Panel);
  EXPECT_EQ(core_.state(), InteractionState::Idle);
  EXPECT_FALSE(core_.hover().has_value());
  frame_.pointHand.select = 1.0;
  frame_.time += 1.0 / 90.0;
  core_.process(frame_, PointTarget::Panel);
  EXPECT_NE(core_.state(), InteractionState::Dragging);
  // Off the panel with the trigger still held: no grab (it needs a fresh press).
  pointAt(p + glm::dvec3(0.0, 0.0, 0.001), 1.0);
  EXPECT_NE(core_.state(), InteractionState::Dragging);
  pointAt(p, 0.0);
  EXPECT_EQ(core_.state(), InteractionState::Hover);
  // A drag under way goes on when the ray crosses the panel.
  pointAt(p, 1.0);
  ASSERT_EQ(core_.state(), InteractionState::Dragging);
  frame_.pointHand.position = p + glm::dvec3(0.03, 0.0, 0.02);
  frame_.time += 1.0 / 90.0;
  core_.process(frame_, PointTarget::Panel);
  EXPECT_EQ(core_.state(), InteractionState::Dragging);
  pointAt(frame_.pointHand.position, 0.0);
  EXPECT_TRUE(sawEvent(InteractionEventKind::Commit));
  EXPECT_EQ(session_.foldCount(), 1u);
}

// Suggested folds (issue 27, 3) reach the core in frames; these helpers send them and press.
class Suggestions : public Interaction {
 protected:
  void offer(std::vector<SuggestedFold> folds) {
    frame_.suggestions = std::move(folds);
    send();
    frame_.suggestions.clear();  // they come in one frame only
  }
  void press(Button button) {
    frame_.buttons = static_cast<std::uint32_t>(button);
    send();
    frame_.buttons = 0;
    send();
  }
  // The fold a FoldSession makes from the seed to the drop point, on the same sheet.
  static Sheet foldedDirectly(const SuggestedFold& fold) {
    FoldSession direct(square());
    direct.beginDragAtDevelopment(fold.seed);
    direct.updateDrag(fold.to);
    EXPECT_TRUE(direct.commit());
    return direct.fixed();
  }

  const SuggestedFold first_{{0.06, 0.06}, {0.06, 0.06, 0.0}, {0.03, 0.06, 0.03}};
  const SuggestedFold second_{{-0.06, 0.06}, {-0.06, 0.06, 0.0}, {-0.06, 0.03, 0.03}};
};

// "Another" goes round the offers; "Take" makes exactly the fold on offer, bit for bit the one a
// session dragging it makes, and then nothing is on offer (the design changed).
TEST_F(Suggestions, TakeMakesTheOfferedFoldAndAnotherGoesRound) {
  EXPECT_EQ(core_.offeredFold(), nullptr);
  offer({first_, second_});
  ASSERT_NE(core_.offeredFold(), nullptr);
  EXPECT_EQ(*core_.offeredFold(), first_);
  EXPECT_EQ(core_.offerCount(), 2u);
  press(Button::NextSuggestion);
  EXPECT_EQ(*core_.offeredFold(), second_);
  EXPECT_EQ(core_.offerIndex(), 1u);
  press(Button::NextSuggestion);
  EXPECT_EQ(*core_.offeredFold(), first_);
  press(Button::NextSuggestion);
  frame_.buttons = static_cast<std::uint32_t>(Button::TakeSuggestion);
  send();
  EXPECT_TRUE(sawEvent(InteractionEventKind::Grab));
  EXPECT_TRUE(sawEvent(InteractionEventKind::Commit));
  frame_.buttons = 0;
  send();
  ASSERT_EQ(session_.foldCount(), 1u);
  EXPECT_TRUE(identical(session_.fixed(), foldedDirectly(second_)));
  EXPECT_EQ(core_.offeredFold(), nullptr);
  press(Button::TakeSuggestion);  // nothing on offer: nothing made
  EXPECT_EQ(session_.foldCount(), 1u);
}

// Offers are for the design they were made for: a fold by hand (or an undo) withdraws them.
TEST_F(Suggestions, AnOfferLapsesWhenTheDesignChanges) {
  offer({first_});
  fold({-0.1, -0.1, 0.0}, {0.02, 0.03, 0.05});
  ASSERT_EQ(session_.foldCount(), 1u);
  EXPECT_EQ(core_.offeredFold(), nullptr);
  press(Button::TakeSuggestion);
  EXPECT_EQ(session_.foldCount(), 1u);
  offer({first_});
  press(Button::Undo);
  EXPECT_EQ(core_.offeredFold(), nullptr);
  press(Button::TakeSuggestion);
  EXPECT_EQ(session_.foldCount(), 0u);
}

// Grabbing the offered point takes the fold as suggested, already at its drop point, and the hand
// adjusts it from there; a grab elsewhere is an ordinary grab.
TEST_F(Suggestions, GrabbingTheOfferedPointStartsFromTheSuggestion) {
  offer({first_});
  // Elsewhere: an ordinary grab, starting where it grabbed.
  dragBy(world({-0.05, -0.05, 0.0}), {0.0, 0.0, 0.0});
  EXPECT_EQ(core_.state(), InteractionState::Dragging);
  expectNear(core_.grabTarget(), core_.grabStart(), 1e-12);
  frame_.buttons = static_cast<std::uint32_t>(Button::Cancel);
  send();
  frame_.buttons = 0;
  pointAt(frame_.pointHand.position, 0.0);
  ASSERT_EQ(session_.foldCount(), 0u);
  // At the offered point (the tip a few millimetres off it): the suggestion, held.
  const glm::dvec3 near = world(first_.grab) + glm::dvec3(0.004, 0.0, 0.003);
  pointAt(near, 0.0);
  pointAt(near, 1.0);
  ASSERT_EQ(core_.state(), InteractionState::Dragging);
  expectNear(core_.grabStart(), first_.grab, 1e-12);
  expectNear(core_.grabTarget(), first_.to, 1e-12);
  // The hand moves 1 cm: the drop point moves with it.
  const glm::dvec3 by = world({0.0, -0.01, 0.0}) - world({0.0, 0.0, 0.0});
  pointAt(near + by, 1.0);
  expectNear(core_.grabTarget(), first_.to + glm::dvec3(0.0, -0.01, 0.0), 1e-12);
  pointAt(near + by, 0.0);
  EXPECT_TRUE(sawEvent(InteractionEventKind::Commit));
  ASSERT_EQ(session_.foldCount(), 1u);
  EXPECT_FALSE(identical(session_.fixed(), foldedDirectly(first_)));
  SuggestedFold adjusted = first_;
  adjusted.to = session_.folds().back().target;
  EXPECT_TRUE(identical(session_.fixed(), foldedDirectly(adjusted)));
}

// A recorded suggestion whose seed lies off the sheet (a hand-edited recording) is dropped.
TEST_F(Suggestions, AnOfferOffTheSheetIsDropped) {
  offer({{{5.0, 5.0}, {5.0, 5.0, 0.0}, {5.0, 5.0, 1.0}}});
  press(Button::TakeSuggestion);
  EXPECT_EQ(session_.foldCount(), 0u);
  EXPECT_EQ(core_.offeredFold(), nullptr);
  EXPECT_EQ(core_.state(), InteractionState::Idle);
}

TEST(PanelRay, HitsFromTheFrontWithUvFromTheTopLeft) {
  const Pose worldFromPanel{{1.0, 2.0, 3.0}, rotation(90, {0, 1, 0})};  // faces +X
  const glm::dvec2 size{0.2, 0.4};
  // From 0.5 m in front, at the panel's centre: uv (0.5, 0.5).
  auto hit = rayOnPanel(worldFromPanel, size, {1.5, 2.0, 3.0}, {-1.0, 0.0, 0.0});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->uv.x, 0.5, 1e-12);
  EXPECT_NEAR(hit->uv.y, 0.5, 1e-12);
  EXPECT_NEAR(hit->distance, 0.5, 1e-12);
  EXPECT_TRUE(hit->onPanel());
  // The panel's +x is world -Z here; its top is +Y: the top-left corner is at uv (0, 0).
  hit = rayOnPanel(worldFromPanel, size, {1.5, 2.2, 3.1}, {-1.0, 0.0, 0.0});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->uv.x, 0.0, 1e-12);
  EXPECT_NEAR(hit->uv.y, 0.0, 1e-12);
  // Off the panel: a hit on its plane, outside [0, 1].
  hit = rayOnPanel(worldFromPanel, size, {1.5, 2.5, 3.0}, {-1.0, 0.0, 0.0});
  ASSERT_TRUE(hit);
  EXPECT_FALSE(hit->onPanel());
  // From behind, pointing away, parallel, or too far: none.
  EXPECT_FALSE(rayOnPanel(worldFromPanel, size, {0.5, 2.0, 3.0}, {1.0, 0.0, 0.0}));
  EXPECT_FALSE(rayOnPanel(worldFromPanel, size, {1.5, 2.0, 3.0}, {1.0, 0.0, 0.0}));
  EXPECT_FALSE(rayOnPanel(worldFromPanel, size, {1.5, 2.0, 3.0}, {0.0, 1.0, 0.0}));
  EXPECT_FALSE(rayOnPanel(worldFromPanel, size, {9.5, 2.0, 3.0}, {-1.0, 0.0, 0.0}, 3.0));
}

TEST(PanelPointerTest, ThePanelKeepsAPressThatBeganOnIt) {
  PanelPointer pointer;
  InputFrame frame;
  frame.pointHand.tracked = true;
  const PanelRayHit on{{0.5, 0.5}, 0.3}, off{{1.5, 0.5}, 0.3};
  EXPECT_EQ(pointer.update(frame, off, false), PointTarget::Sheet);
  EXPECT_EQ(pointer.update(frame, on, false), PointTarget::Panel);
  EXPECT_FALSE(pointer.buttonDown());
  frame.pointHand.select = 1.0;
  EXPECT_EQ(pointer.update(frame, on, false), PointTarget::Panel);
  EXPECT_TRUE(pointer.buttonDown());
  // Dragged past the edge (a slider): still the panel's, button still down.
  EXPECT_EQ(pointer.update(frame, off, false), PointTarget::Panel);
  EXPECT_TRUE(pointer.buttonDown());
  frame.pointHand.select = 0.0;
  EXPECT_EQ(pointer.update(frame, off, false), PointTarget::Sheet);
  EXPECT_FALSE(pointer.buttonDown());
  // A press off the panel that sweeps onto it: the panel has the ray but not the button.
  frame.pointHand.select = 1.0;
  EXPECT_EQ(pointer.update(frame, off, false), PointTarget::Sheet);
  EXPECT_EQ(pointer.update(frame, on, false), PointTarget::Panel);
  EXPECT_FALSE(pointer.buttonDown());
  // A drag of the sheet keeps the point hand whatever the ray crosses.
  EXPECT_EQ(pointer.update(frame, on, true), PointTarget::Sheet);
  frame.pointHand.select = 0.0;
  // No aim, or an untracked hand: the sheet's.
  EXPECT_EQ(pointer.update(frame, std::nullopt, false), PointTarget::Sheet);
  frame.pointHand.tracked = false;
  EXPECT_EQ(pointer.update(frame, on, false), PointTarget::Sheet);
}

}  // namespace
}  // namespace curvefold

namespace curvefold {
namespace {

// Issue 17, 1: while a drag passes the paper through itself the core says how many triangle pairs
// and which triangles, pulses once as it starts, and after the commit remembers the count of that
// fold (until an undo).
TEST(InteractionSelfIntersection, ADragThroughTheSheetIsWatchedAndPulsesOnce) {
  FoldSession session(makeSurface("cylinder", {{"resolution", 16}}));
  const Pose frame{};  // world = sheet
  InteractionCore core(session, frame);
  InputFrame input;
  input.sheetHand.tracked = true;
  input.pointHand.tracked = true;
  auto send = [&](const glm::dvec3& at, double select) {
    input.time += 1.0 / 90.0;
    input.pointHand.position = at;
    input.pointHand.select = select;
    core.process(input);
  };
  // The tube's top folded down through a slanted plane, out through the far wall (as in
  // test_self_intersection.cpp), in steps.
  const glm::dvec3 grab(0.045, 0.1, 0.0), normal = glm::normalize(glm::dvec3(-1, -1, 0));
  const glm::dvec3 through(0.0, 0.025, 0.0);
  const glm::dvec3 target = grab - 2.0 * glm::dot(grab - through, normal) * normal;
  send(grab, 0.0);
  send(grab, 1.0);
  ASSERT_EQ(core.state(), InteractionState::Dragging);
  int pulses = 0;
  bool crossed = false;
  for (int i = 1; i <= 20; ++i) {
    send(grab + (target - grab) * (i / 20.0), 1.0);
    for (const HapticPulse& pulse : core.haptics())
      pulses += pulse.amplitude == kIntersectionPulse.amplitude &&
                pulse.duration == kIntersectionPulse.duration;
    if (core.intersectionPairs() > 0) {
      crossed = true;
      EXPECT_FALSE(core.intersectingTriangles().empty());
    }
  }
  EXPECT_TRUE(crossed);
  EXPECT_GE(pulses, 1);
  const std::size_t pairs = core.intersectionPairs();
  EXPECT_GT(pairs, 0u);
  send(target, 0.0);  // release: committed
  EXPECT_EQ(session.foldCount(), 1u);
  EXPECT_EQ(core.intersectionPairs(), 0u);
  EXPECT_TRUE(core.intersectingTriangles().empty());
  EXPECT_EQ(core.lastCommitIntersections(), pairs);
  input.buttons = std::uint32_t(Button::Undo);
  send(target, 0.0);
  EXPECT_EQ(core.lastCommitIntersections(), 0u);
}

}  // namespace
}  // namespace curvefold
