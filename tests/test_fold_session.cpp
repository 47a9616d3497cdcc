#include <random>

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sheet_fixtures.hpp"

namespace curvefold {
namespace {

using testing::expectInvariants;
using testing::flatGrid;

// A repeatable drag: grab near a point of the current sheet, pass through a few targets, commit.
void drag(FoldSession& session, const glm::dvec3& near, const std::vector<glm::dvec3>& targets) {
  session.beginDragNear(near);
  for (const glm::dvec3& target : targets) {
    session.updateDrag(target);
    expectInvariants(session.current(), session.initial());
  }
  session.commit();
  expectInvariants(session.fixed(), session.initial());
}

std::vector<FoldRecord> firstFolds(const FoldSession& session, std::size_t count) {
  return {session.folds().begin(), session.folds().begin() + count};
}

TEST(FoldSession, CommittedDragEqualsReplayedRecordBitForBit) {
  FoldSession session(flatGrid(8, 6, 0.025));
  drag(session, {0.013, 0.011, 0.0}, {{0.05, 0.02, 0.02}, {0.1, 0.04, 0.05}, {0.12, 0.05, 0.06}});
  ASSERT_EQ(session.foldCount(), 1u);
  const FoldRecord& fold = session.folds()[0];
  EXPECT_EQ(fold.target, (glm::dvec3{0.12, 0.05, 0.06}));
  EXPECT_NEAR(fold.seed.x, 0.013, 1e-15);  // a surface point, not a vertex
  EXPECT_NEAR(fold.seed.y, 0.011, 1e-15);
  EXPECT_TRUE(identical(session.fixed(), applyFold(session.initial(), fold)));
  // The grabbed point is now a vertex at the target.
  const Sheet& sheet = session.fixed();
  bool found = false;
  for (VertexIndex v = 0; v < sheet.vertexCount(); ++v)
    found |=
        sheet.development[v] == fold.seed && glm::distance(sheet.positions[v], fold.target) < 1e-12;
  EXPECT_TRUE(found);
}

TEST(FoldSession, CancelRestoresTheFixedSheetBitForBit) {
  FoldSession session(flatGrid(6, 6, 0.03));
  drag(session, {0.0, 0.0, 0.0}, {{0.09, 0.02, 0.03}});
  const Sheet before = session.fixed();
  session.beginDragNear({0.17, 0.16, 0.0});
  session.updateDrag({0.05, 0.05, 0.1});
  EXPECT_FALSE(identical(session.current(), before));
  session.cancel();
  EXPECT_FALSE(session.dragging());
  EXPECT_TRUE(identical(session.current(), before));
  EXPECT_EQ(session.foldCount(), 1u);
}

TEST(FoldSession, TargetAtTheGrabbedPointIsANoOp) {
  FoldSession session(flatGrid(4, 4, 0.05));
  const glm::dvec3 grabbed = session.beginDragNear({0.07, 0.03, 0.0});
  session.updateDrag({0.15, 0.1, 0.1});
  session.updateDrag(grabbed);  // back to the start: unfolded again
  EXPECT_FALSE(session.hasPlane());
  EXPECT_TRUE(session.current().tags.empty());
  EXPECT_FALSE(session.commit());
  EXPECT_EQ(session.foldCount(), 0u);
  EXPECT_TRUE(identical(session.fixed(), session.initial()));
}

// Issue 13, D14: shorter than minimumDrag() is no fold, however the plane would cut the sheet.
TEST(FoldSession, DragShorterThanTheMinimumIsNoFold) {
  FoldSession session(flatGrid(4, 4, 0.05));
  const glm::dvec3 grabbed = session.beginDragNear({0.2, 0.2, 0.0});
  for (double length : {1e-12, 1e-10, 1e-9, 0.5 * session.minimumDrag()}) {
    session.updateDrag(grabbed + glm::dvec3(0.0, 0.0, length));
    EXPECT_FALSE(session.hasPlane()) << length;
    EXPECT_TRUE(session.current().tags.empty()) << length;
  }
  EXPECT_FALSE(session.commit());
  EXPECT_TRUE(identical(session.fixed(), session.initial()));
  session.beginDragNear({0.2, 0.2, 0.0});
  session.updateDrag(grabbed + glm::dvec3(0.0, 0.0, 2.0 * session.minimumDrag()));
  EXPECT_TRUE(session.hasPlane());
}

// Issue 13, E22: a grab uses the picked triangle and the session's adjacency instead of scanning
// every triangle; the sheet it makes is the scan's, bit for bit, inside a triangle, on an edge and
// at a vertex.
TEST(FoldSession, AGrabWithHintsMakesTheScansSheet) {
  const Sheet sheet = flatGrid(6, 6, 0.04);
  int edgeSplits = 0;
  // Inside, on a grid line, on either diagonal, at a vertex, on the boundary.
  for (const glm::dvec3 near :
       {glm::dvec3(0.101, 0.093, 0.0), glm::dvec3(0.08, 0.093, 0.0), glm::dvec3(0.1, 0.1, 0.0),
        glm::dvec3(0.1, 0.14, 0.0), glm::dvec3(0.12, 0.12, 0.0), glm::dvec3(0.0, 0.05, 0.0)}) {
    FoldSession session(sheet);
    const SurfacePoint point = closestSurfacePoint(sheet, near);
    session.beginDrag(point);
    const VertexInsertion scanned = insertVertexAt(sheet, developmentOf(sheet, point));
    edgeSplits += scanned.sheet.triangleCount() == sheet.triangleCount() + 2;
    EXPECT_TRUE(identical(session.fixed(), scanned.sheet)) << near.x << ", " << near.y;
    EXPECT_EQ(session.grabbedVertex(), scanned.vertex);
    session.cancel();
    EXPECT_TRUE(identical(session.fixed(), sheet));
  }
  EXPECT_GE(edgeSplits, 2);  // the adjacency path was taken
}

// Issue 13, D15 (found by fuzz_fold; its input is in fuzz/corpus/fold): a grab inside a thin
// triangle, next to a sharp corner but farther than the grab snap, made a piece thinner than the
// floor. Grabs near the corners of thin triangles make nothing thinner than the cut floor.
TEST(FoldSession, AGrabInAThinTriangleMakesNoSliver) {
  Sheet sheet = flatGrid(1, 1, 0.2);
  for (glm::dvec3& p : sheet.positions) p.y *= 1e-5;  // 20 cm by 2 micrometres: thin triangles
  for (glm::dvec2& q : sheet.development) q.y *= 1e-5;
  ASSERT_NO_THROW(validate(sheet));
  const double floor = kRelativeCutFeatureSize * sheetSize(sheet);
  for (const glm::dvec3 weights : {glm::dvec3(6.6e-6, 0.99998, 1.4e-5),
                                   glm::dvec3(1e-5, 1e-5, 1.0 - 2e-5), glm::dvec3(0.3, 0.3, 0.4)}) {
    FoldSession session(sheet);
    session.beginDrag({0, {weights.x, weights.y, weights.z}});
    EXPECT_GE(measure(session.fixed()).minRelativeHeight * sheetSize(sheet), floor)
        << weights.x << ", " << weights.y;
  }
  FoldSession middle(sheet);  // well inside: a new vertex
  middle.beginDrag({0, {0.3, 0.3, 0.4}});
  EXPECT_EQ(middle.fixed().vertexCount(), sheet.vertexCount() + 1);
}

// Found by fuzz_fold (its input is in fuzz/corpus/fold/narrow_strip_oblique_cut): a cylinder
// strip 0.08 degrees around (66 micrometres wide, 21 cm long, six triangles), grabbed 10 nm from
// its edge near a corner (a triangle 10 nm high and 21 cm long) and dragged far and obliquely, cut
// that triangle 1.5 mm from its far corner into pieces 66 picometres high: under the degenerate
// floor, and no plane shift within reach helps. The preview stays the unfolded sheet (never an
// invalid one) and a commit there is refused with the reason.
TEST(FoldSession, AnObliqueCutAcrossANarrowStripMakesNoSliver) {
  const Sheet strip = makeSurface("cylinder", {{"angle", 0.083720748377963894}, {"resolution", 1}});
  FoldSession session(strip);
  session.beginDrag({1,
                     {1.0 - 0.00045949875321976843 - 5.325616574754883e-06, 0.00045949875321976843,
                      5.325616574754883e-06}});
  const Sheet grabbed = session.fixed();
  session.updateDrag({-0.16073013397838112, 0.10509449319014343, 0.17789703114591915});
  const SheetReport report = measure(session.current());
  EXPECT_EQ(report.firstProblem, "");
  EXPECT_GE(report.minRelativeHeight, kRelativeFeatureSize);
  EXPECT_TRUE(identical(session.current(), grabbed));
  EXPECT_FALSE(session.hasPlane());
  EXPECT_FALSE(session.commit());
  EXPECT_NE(session.refusal().find("not kept"), std::string::npos) << session.refusal();
  EXPECT_TRUE(identical(session.fixed(), strip));
  // The same drag ending elsewhere folds as before.
  session.beginDrag({1,
                     {1.0 - 0.00045949875321976843 - 5.325616574754883e-06, 0.00045949875321976843,
                      5.325616574754883e-06}});
  session.updateDrag(session.grabbedPoint() + glm::dvec3(0.0, 0.05, 0.05));
  EXPECT_TRUE(session.commit()) << session.refusal();
  expectInvariants(session.fixed(), strip);
}

bool sameAdjacency(const SheetAdjacency& a, const SheetAdjacency& b) {
  return a.triangles.offsets == b.triangles.offsets &&
         a.triangles.triangles == b.triangles.triangles &&
         a.neighbors.offsets == b.neighbors.offsets && a.neighbors.vertices == b.neighbors.vertices;
}

// Issue 13, E22: the grab's adjacency is patched where the insertion touched it (equal to a full
// rebuild, row for row), and the temporal sheet stays equal to the fixed one between drags
// (through grabs inside triangles, on edges and at vertices; commits, refused drags, cancels,
// undos and redos), so a grab copies no sheet.
TEST(FoldSession, AGrabPatchesTheAdjacencyAndKeepsTheTemporalSheetInStep) {
  FoldSession session(makeSurface("cylinder", {{"resolution", 12}}));
  std::mt19937 random(22);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int inserted = 0;
  for (int step = 0; step < 60; ++step) {
    const Sheet before = session.fixed();
    const Sheet& fixed = session.fixed();
    const auto t = static_cast<TriangleIndex>(random() % fixed.triangleCount());
    // Some grabs at a corner or on an edge (a vertex snap, an edge split), most inside.
    double a = unit(random), b = unit(random);
    if (step % 5 == 1) b = 0.0;
    if (step % 5 == 2) a = b = 0.0;
    if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
    const glm::dvec3 grabbed = session.beginDrag({t, {1.0 - a - b, a, b}});
    ASSERT_TRUE(identical(session.current(), session.fixed())) << "step " << step;
    InsertionUndo undo;
    Sheet after = before;
    insertVertexInPlace(after, developmentOf(before, {t, {1.0 - a - b, a, b}}), &undo);
    ASSERT_TRUE(identical(after, session.fixed())) << "step " << step;
    if (after.vertexCount() != before.vertexCount()) {
      ++inserted;
      SheetAdjacency patched;
      adjacencyAfterInsertion(buildAdjacency(before), after, undo, patched);
      EXPECT_TRUE(sameAdjacency(patched, buildAdjacency(after))) << "step " << step;
    }
    session.updateDrag(
        grabbed + 0.04 * glm::dvec3(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5));
    switch (step % 4) {
      case 0:
        session.cancel();
        break;
      case 1:
        session.commit();
        break;
      case 2:  // back to the start: a grab without a fold, which commits nothing
        session.updateDrag(grabbed);
        EXPECT_FALSE(session.commit());
        break;
      default:
        session.commit();
        session.undo();
        if (step % 8 == 3) session.redo();
    }
  }
  EXPECT_GT(inserted, 30);
  session.beginDragNear(session.fixed().positions[0]);
  EXPECT_TRUE(identical(session.current(), session.fixed()));
}

// Issue 13, D15: a plane just outside the on-plane tolerance through a thin triangle (made by
// grabbing near an edge) left a triangle of height 5e-13 that validate() rejects, and the session
// committed it without validating. Planes from just outside the tolerance to a thousand times it
// from a thin triangle's sharp corner: the plane moves through the corner instead (an exact
// reflection still), every fold commits, no triangle is thinner than the minimum feature size, and
// the recorded fold replays to the same sheet bit for bit.
TEST(FoldSession, PlanesJustOutsideTheToleranceSnapThroughTheVertex) {
  const double cell = 0.05;
  const Sheet grid = flatGrid(4, 4, cell);
  const double feature = kRelativeFeatureSize * sheetSize(grid);
  std::mt19937 random(15);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int shifted = 0;
  for (int trial = 0; trial < 300; ++trial) {
    FoldSession session(grid);
    // Just off the diagonal of the cell at (1, 1): a vertex that makes two thin triangles.
    const double along = 0.3 + 0.4 * std::abs(unit(random));
    const double off = 2e-4 * cell * (1.0 + std::abs(unit(random)));
    const glm::dvec2 seed =
        glm::dvec2(cell, cell) + along * glm::dvec2(cell, cell) + off * glm::dvec2(0.7071, -0.7071);
    const glm::dvec3 grabbed = session.beginDragAtDevelopment(seed);
    const glm::dvec3 corner =
        trial % 2 ? glm::dvec3(cell, cell, 0.0) : glm::dvec3(2 * cell, 2 * cell, 0.0);
    // The corner just on the far side of the plane, the grabbed vertex on the near (reflected)
    // side: the plane cuts the thin triangles next to their sharp corner.
    glm::dvec3 normal = glm::normalize(glm::dvec3(unit(random), unit(random), unit(random)));
    if (glm::dot(grabbed - corner, normal) > 0.0) normal = -normal;
    const double offset = session.epsilon() * std::pow(10.0, 0.0004 + 1.5 * (1.0 + unit(random)));
    const glm::dvec3 point = corner - offset * normal;
    const glm::dvec3 target = grabbed - 2.0 * glm::dot(grabbed - point, normal) * normal;
    const ReflectionChanges& changes = session.updateDrag(target);
    shifted += changes.planeShift != 0.0;
    EXPECT_LE(std::abs(changes.planeShift), kRelativeMaxPlaneShift * sheetSize(grid));
    ASSERT_TRUE(session.commit()) << "trial " << trial << ": " << session.refusal();
    EXPECT_NO_THROW(validate(session.fixed())) << "trial " << trial;
    EXPECT_GE(measure(session.fixed()).minRelativeHeight * sheetSize(grid), feature)
        << "trial " << trial;
    EXPECT_TRUE(identical(replayFolds(grid, session.folds()), session.fixed()))
        << "trial " << trial;
  }
  EXPECT_GT(shifted, 30);  // the near planes moved; the far ones did not need to
  RecordProperty("shifted", shifted);
}

// Issue 13, A3: points whose squared distance would overflow are refused, never turned into a
// default (invalid) surface point.
TEST(FoldSession, PointsAbsurdlyFarFromTheSheetAreRefused) {
  const Sheet sheet = flatGrid(4, 4, 0.05);
  EXPECT_THROW(closestSurfacePoint(sheet, {1e155, 0.0, 0.0}), InvalidSheet);
  EXPECT_THROW(closestSurfacePoint(sheet, {0.0, -1e300, 0.0}), InvalidSheet);
  EXPECT_NO_THROW(closestSurfacePoint(sheet, {1e4, 0.0, 0.0}));  // far, but within reach
  // Issue 40: a NaN lies nowhere, not "too far from the sheet".
  try {
    closestSurfacePoint(sheet, {std::nan(""), 0.0, 0.0});
    ADD_FAILURE() << "a NaN point was taken";
  } catch (const InvalidSheet& e) {
    EXPECT_EQ(std::string(e.what()),
              "point (nan, 0, 0) is not a point: its coordinates must be finite numbers");
  }
  FoldSession session(sheet);
  session.beginDragNear({0.1, 0.1, 0.0});
  EXPECT_THROW(session.updateDrag({1e300, 0.0, 0.0}), InvalidSheet);
  EXPECT_NO_THROW(session.updateDrag({0.1, 0.1, 0.05}));
  EXPECT_TRUE(session.commit());
}

TEST(FoldSession, UndoRedoAcrossKeyframes) {
  FoldSession session(flatGrid(10, 10, 0.02));
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(0.0, 0.2);
  for (int i = 0; i < 11; ++i)
    drag(session, {coordinate(random), coordinate(random), 0.0},
         {{coordinate(random), coordinate(random), 0.05 + coordinate(random) * 0.2}});
  ASSERT_EQ(session.foldCount(), 11u);
  const Sheet afterEleven = session.fixed();
  const std::vector<FoldRecord> all = session.folds();

  for (int i = 0; i < 4; ++i) ASSERT_TRUE(session.undo());
  EXPECT_TRUE(identical(session.fixed(), replayFolds(session.initial(), firstFolds(session, 7))));
  ASSERT_TRUE(session.redo());
  ASSERT_TRUE(session.redo());
  EXPECT_TRUE(identical(session.fixed(), replayFolds(session.initial(), firstFolds(session, 9))));
  ASSERT_TRUE(session.redo());
  ASSERT_TRUE(session.redo());
  EXPECT_FALSE(session.redo());
  EXPECT_TRUE(identical(session.fixed(), afterEleven));

  while (session.undo()) {
  }
  EXPECT_EQ(session.foldCount(), 0u);
  EXPECT_TRUE(identical(session.fixed(), session.initial()));

  // A new fold after undo drops the redo history.
  ASSERT_TRUE(session.redo());
  drag(session, {0.1, 0.1, 0.0}, {{0.12, 0.1, 0.05}});
  EXPECT_EQ(session.folds().size(), 2u);
  EXPECT_FALSE(session.canRedo());
  EXPECT_TRUE(identical(session.fixed(), replayFolds(session.initial(), session.folds())));
  EXPECT_EQ(session.folds()[0].seed, all[0].seed);
}

// undoTo(n) leaves the session as `while (foldCount() > n) undo();` does, folding the sheet again
// once: the same folds (a group whole, though it reaches below n), the same sheet bit for bit,
// the same redo.
TEST(FoldSession, UndoToTakesBackWholeGroupsAsRepeatedUndoDoes) {
  FoldSession made(flatGrid(10, 10, 0.02));
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(0.0, 0.2);
  for (int i = 0; i < 11; ++i)
    drag(made, {coordinate(random), coordinate(random), 0.0},
         {{coordinate(random), coordinate(random), 0.05 + coordinate(random) * 0.2}});
  ASSERT_EQ(made.foldCount(), 11u);
  std::vector<FoldRecord> records = made.folds();
  for (std::size_t i = 4; i < 7; ++i) records[i].group = 1;  // folds 5 to 7 one group
  FoldSession stepped(made.initial()), once(made.initial());
  stepped.applyRecords(records);
  once.applyRecords(records);
  for (const std::size_t to : {9u, 6u}) {
    while (stepped.foldCount() > to) stepped.undo();
    const std::size_t before = once.foldCount();
    EXPECT_EQ(once.undoTo(to), before - stepped.foldCount());
    EXPECT_EQ(once.foldCount(), stepped.foldCount());
    EXPECT_TRUE(identical(once.fixed(), stepped.fixed()));
  }
  EXPECT_EQ(once.foldCount(), 4u);  // the group of folds 5 to 7 went whole
  EXPECT_EQ(once.undoTo(4), 0u);    // nothing left to take back
  ASSERT_TRUE(once.redo());
  ASSERT_TRUE(stepped.redo());
  EXPECT_EQ(once.foldCount(), 7u);
  EXPECT_TRUE(identical(once.fixed(), stepped.fixed()));
  EXPECT_TRUE(identical(once.fixed(), replayFolds(once.initial(), firstFolds(once, 7))));
}

// A search folds, measures and takes back to one point again and again (tucks, pleats, rings):
// undoTo keeps that point's sheet and adjacency and copies them back. Each return is the sheet
// the records make, a fold made there is the one their replay makes (the adjacency is the
// sheet's), and after a restart from another sheet, no folds is that sheet, not the one kept.
TEST(FoldSession, UndoToTheSamePointAgainIsTheSheetItsRecordsMake) {
  FoldSession session(flatGrid(10, 10, 0.02));
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(0.0, 0.2);
  auto randomDrag = [&] {
    drag(session, {coordinate(random), coordinate(random), 0.0},
         {{coordinate(random), coordinate(random), 0.05 + coordinate(random) * 0.2}});
  };
  for (int i = 0; i < 10; ++i) randomDrag();
  ASSERT_EQ(session.foldCount(), 10u);
  for (int round = 0; round < 3; ++round) {
    randomDrag();
    randomDrag();
    session.undoTo(9);
    ASSERT_EQ(session.foldCount(), 9u);
    EXPECT_TRUE(identical(session.fixed(), replayFolds(session.initial(), firstFolds(session, 9))))
        << "round " << round;
  }
  randomDrag();
  ASSERT_EQ(session.foldCount(), 10u);
  EXPECT_TRUE(identical(session.fixed(), replayFolds(session.initial(), session.folds())));

  session.undoTo(0);
  session.restartFrom(flatGrid(8, 8, 0.025));
  randomDrag();
  ASSERT_EQ(session.undoTo(0), 1u);
  EXPECT_TRUE(identical(session.fixed(), session.initial()));
}

// docs/design.md 8: the fixed + temporal pair stays below three sheets while dragging.
TEST(FoldSession, FixedAndTemporalStayBelowThreeSheets) {
  FoldSession session(flatGrid(100, 100, 0.002));
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 corner{0.2 * (i % 2), 0.2 * (i / 2), 0.0};
    session.beginDragNear(corner);
    session.updateDrag(corner + glm::dvec3(0.05 - 0.1 * (i % 2), 0.03, 0.04));
    const SessionMemory memory = session.memoryUse();
    const std::size_t oneSheet = sheetBytes(session.current());
    // The budget is 3; two sheets and the temporal's spare capacity stay well inside it.
    EXPECT_LT(memory.fixed + memory.temporal, 2.5 * oneSheet);
    ASSERT_TRUE(session.commit());
  }
}

TEST(FoldSession, UpdateReportsWhatChanged) {
  FoldSession session(flatGrid(20, 20, 0.01));
  session.beginDragNear({0.0, 0.0, 0.0});
  const ReflectionChanges& changes = session.updateDrag({0.04, 0.0, 0.04});
  // Only the corner region moved: far fewer vertices than the sheet has.
  EXPECT_GT(changes.movedVertices.size(), 0u);
  EXPECT_LT(changes.movedVertices.size(), session.current().vertexCount() / 4);
  for (VertexIndex v : changes.movedVertices) EXPECT_LT(session.current().development[v].x, 0.04);
  EXPECT_EQ(changes.firstNewVertex, session.fixed().vertexCount());
}

}  // namespace
}  // namespace curvefold
