// Degenerate geometry (issue: hardening): planes through vertices and along edges, targets next
// to the grabbed point, grabbing boundary and slit vertices, folding onto an already folded
// part, very thin sheets, and sheets from a millimetre to a kilometre. No NaN, no sliver, no crash.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sheet_fixtures.hpp"

namespace curvefold {
namespace {

using testing::expectInvariants;

// No NaN anywhere and every triangle well clear of degenerate.
void expectClean(const Sheet& sheet, const Sheet& initial) {
  expectInvariants(sheet, initial);
  for (const glm::dvec3& p : sheet.positions)
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  EXPECT_GT(measure(sheet).minRelativeHeight, 1e-9);
}

TEST(Degenerate, PlaneAlongAnExistingEdgeHingesOnIt) {
  // The square's diagonal (0,0)-(1,1) is edge (0, 2); dragging corner 1 onto corner 3 reflects
  // through exactly that line.
  const Sheet square = testing::unitSquare();
  const ReflectionResult result = reflect(square, 1, bisectorPlane({1, 0, 0}, {0, 1, 0}));
  expectClean(result.sheet, square);
  EXPECT_EQ(result.sheet.vertexCount(), 4u);
  EXPECT_EQ(result.sheet.triangleCount(), 2u);
  const auto creases = creaseEdges(result.sheet, buildEdgeTopology(result.sheet));
  ASSERT_EQ(creases.size(), 1u);
  EXPECT_EQ(creases[0].edge, Edge::of(0, 2));
  EXPECT_NEAR(std::abs(creases[0].foldAngle), 180.0, 1e-9);
}

TEST(Degenerate, PlaneThroughAVertexCutsOnlyTheOtherEdges) {
  // Corner 0 dragged across the line x + 2y = 1, which passes through the grid vertex (1, 0) and
  // cuts edges elsewhere: that vertex stays put (snapped onto the plane), the cuts are new.
  const Sheet grid = testing::flatGrid(2, 2, 1.0);
  const glm::dvec3 p0{0, 0, 0};
  const glm::dvec3 p1 = glm::dvec3(1, 2, 0) * (2.0 / 5.0);  // reflection of p0 in x + 2y = 1
  const ReflectionResult result = reflect(grid, 0, bisectorPlane(p0, p1));
  expectClean(result.sheet, grid);
  EXPECT_GT(result.sheet.vertexCount(), grid.vertexCount());
  for (VertexIndex v = 0; v < grid.vertexCount(); ++v) {
    if (grid.development[v] == glm::dvec2(1, 0)) {
      EXPECT_EQ(result.sheet.positions[v], grid.positions[v]);
    }
  }
}

TEST(Degenerate, TargetsNextToTheGrabbedPoint) {
  FoldSession session(makeSurface("square", {{"resolution", 12}}));
  const glm::dvec3 grabbed = session.beginDragNear({0.03, 0.02, 0.0});
  for (double offset : {0.0, 1e-15, 1e-12, -1e-12}) {
    session.updateDrag(grabbed + glm::dvec3(offset, offset, offset));
    EXPECT_FALSE(session.hasPlane()) << offset;
    expectClean(session.current(), session.initial());
  }
  // Just past the snap distance the plane is real but the fold is tiny: still clean.
  session.updateDrag(grabbed + glm::dvec3(0, 0, 1e-6));
  EXPECT_TRUE(session.hasPlane());
  expectClean(session.current(), session.initial());
  EXPECT_TRUE(session.commit());
  expectClean(session.fixed(), session.initial());
}

TEST(Degenerate, GrabbingBoundaryAndSlitVertices) {
  // A full cylinder has a slit at -z; grab a seam vertex, then a rim vertex, and fold each.
  FoldSession session(makeSurface("cylinder", {{"resolution", 24}}));
  const Sheet& initial = session.initial();
  VertexIndex seam = kNoIndex;
  for (const TaggedEdge& tag : initial.tags)
    if (tag.kind == EdgeKind::Slit) seam = tag.edge.a;
  ASSERT_NE(seam, kNoIndex);
  const glm::dvec3 seamPoint = initial.positions[seam];
  session.beginDragNear(seamPoint);
  ASSERT_EQ(session.grabbedPoint(), seamPoint);
  session.updateDrag(seamPoint + glm::dvec3(0.0, 0.01, 0.03));
  ASSERT_TRUE(session.commit());
  expectClean(session.fixed(), initial);
  const glm::dvec3 rim{0.045, 0.105, 0.0};
  session.beginDragNear(rim);
  session.updateDrag(rim + glm::dvec3(-0.03, -0.02, 0.0));
  ASSERT_TRUE(session.commit());
  expectClean(session.fixed(), initial);
  // The slit is still there (validate checks it is boundary), split where the folds crossed it.
  auto slitCount = [](const Sheet& sheet) {
    std::size_t slits = 0;
    for (const TaggedEdge& tag : sheet.tags) slits += tag.kind == EdgeKind::Slit;
    return slits;
  };
  EXPECT_GE(slitCount(session.fixed()), slitCount(initial));
}

TEST(Degenerate, FoldingAPartAlreadyFoldedOntoItself) {
  // Fold a square flat in half (the halves coincide), then fold the doubled layer again, twice.
  FoldSession session(makeSurface("square", {{"resolution", 16}}));
  session.beginDragNear({-0.1, 0.0, 0.0});
  session.updateDrag({0.1, 0.0, 0.0});  // bisector x = 0: a 180-degree fold onto the right half
  ASSERT_TRUE(session.commit());
  expectClean(session.fixed(), session.initial());
  for (const glm::dvec3 corner : {glm::dvec3{0.1, 0.1, 0.0}, glm::dvec3{0.1, -0.1, 0.0}}) {
    session.beginDragNear(corner);
    session.updateDrag(corner + glm::dvec3(-0.05, -0.05 * std::copysign(1.0, corner.y), 0.0));
    ASSERT_TRUE(session.commit());
    expectClean(session.fixed(), session.initial());
  }
  // Both layers were folded by both corner folds: the creases stack in pairs.
  const auto curves = creaseCurves(session.fixed(), buildEdgeTopology(session.fixed()));
  EXPECT_GE(curves.size(), 3u);
}

TEST(Degenerate, VeryThinSheet) {
  FoldSession session(
      makeSurface("rectangle", {{"width", 0.3}, {"height", 0.001}, {"resolution", 300}}));
  session.beginDragNear({0.15, 0.0, 0.0});
  session.updateDrag({0.1, 0.0, 0.04});
  ASSERT_TRUE(session.commit());
  expectClean(session.fixed(), session.initial());
  session.beginDragNear({-0.15, 0.0005, 0.0});
  session.updateDrag({-0.1, 0.0003, -0.03});
  ASSERT_TRUE(session.commit());
  expectClean(session.fixed(), session.initial());
}

class SheetScale : public ::testing::TestWithParam<double> {};

TEST_P(SheetScale, FoldsTheSameAtEveryScale) {
  const double size = GetParam();
  FoldSession session(makeSurface("square", {{"size", size}, {"resolution", 20}}));
  // The same three folds, scaled.
  const glm::dvec3 drags[][2] = {{{0.5, 0.5, 0.0}, {0.2, 0.25, 0.3}},
                                 {{-0.5, 0.5, 0.0}, {-0.2, 0.1, 0.35}},
                                 {{0.0, -0.5, 0.0}, {0.05, -0.2, -0.2}}};
  for (const auto& drag : drags) {
    session.beginDragNear(drag[0] * size);
    session.updateDrag(drag[1] * size);
    ASSERT_TRUE(session.commit());
    expectClean(session.fixed(), session.initial());
  }
  // Scale-free: the relative edge-length error and crease count do not depend on the size.
  EXPECT_LT(measure(session.fixed()).maxEdgeLengthError / size, 1e-14);
  EXPECT_GT(creaseEdges(session.fixed(), buildEdgeTopology(session.fixed())).size(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Degenerate, SheetScale, ::testing::Values(1e-3, 0.2, 1e3));

}  // namespace
}  // namespace curvefold
