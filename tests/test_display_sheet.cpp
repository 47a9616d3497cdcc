// The coarse sheet that is drawn: planar simplification and the display session that follows a
// fold session. "Same surface" is checked through the development, which both sheets share: every
// vertex of one, located in the other's development, has the same 3D position there.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/display_session.hpp"
#include "engine/geometry/planar_simplification.hpp"
#include "engine/geometry/surface_point.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sheet_fixtures.hpp"

namespace curvefold {
namespace {

// Every vertex of `from`, located in `in` by its development point, sits at the same 3D position.
void expectVerticesOnSurface(const Sheet& from, const Sheet& in, const char* what) {
  const double size = sheetSize(in);
  double worst = 0.0;
  for (VertexIndex v = 0; v < from.vertexCount(); ++v) {
    const std::optional<SurfacePoint> point =
        locateDevelopmentPoint(in, from.development[v], 1e-9 * size);
    ASSERT_TRUE(point) << what << ": vertex " << v << " lies outside the other development";
    worst = std::max(worst, glm::distance(positionOf(in, *point), from.positions[v]));
  }
  EXPECT_LE(worst, 1e-8 * size) << what;
}

void expectSameSurface(const Sheet& coarse, const Sheet& fine) {
  expectVerticesOnSurface(coarse, fine, "coarse in fine");
  expectVerticesOnSurface(fine, coarse, "fine in coarse");
}

double taggedLength(const Sheet& sheet, EdgeKind kind) {
  double length = 0.0;
  for (const TaggedEdge& tag : sheet.tags)
    if (tag.kind == kind)
      length += glm::distance(sheet.positions[tag.edge.a], sheet.positions[tag.edge.b]);
  return length;
}

TEST(PlanarSimplification, FlatGridBecomesTwoTriangles) {
  const Sheet grid = testing::flatGrid(12, 7, 0.01);
  const PlanarSimplification coarse = simplifyPlanar(grid);
  testing::expectInvariants(coarse.sheet, grid);
  EXPECT_EQ(coarse.sheet.triangleCount(), 2u);
  ASSERT_EQ(coarse.originalVertex.size(), coarse.sheet.vertexCount());
  for (VertexIndex v = 0; v < coarse.sheet.vertexCount(); ++v)
    EXPECT_EQ(coarse.sheet.positions[v], grid.positions[coarse.originalVertex[v]]);
  expectSameSurface(coarse.sheet, grid);
}

TEST(PlanarSimplification, HoleAndNotchKeepTheirShape) {
  // A 9x9 grid without its centre cell (a hole) and without one corner cell (a notch).
  const Sheet grid = testing::flatGrid(
      9, 9, 0.01, [](int i, int j) { return !(i == 4 && j == 4) && !(i == 8 && j == 8); });
  const PlanarSimplification coarse = simplifyPlanar(grid);
  testing::expectInvariants(coarse.sheet, grid);
  EXPECT_LT(coarse.sheet.triangleCount(), 24u);
  expectSameSurface(coarse.sheet, grid);
}

TEST(PlanarSimplification, BumpyGridKeepsEveryTriangle) {
  Sheet grid = testing::flatGrid(6, 6, 0.01);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> bump(-1e-3, 1e-3);
  for (glm::dvec3& p : grid.positions) p.z = bump(random);
  EXPECT_EQ(simplifyPlanar(grid).sheet.triangleCount(), grid.triangleCount());
}

// Every surface of the catalog, before and after a fold: far fewer triangles, a valid sheet, the
// same surface, the same creases and slit.
TEST(PlanarSimplification, KeepsEverySurfaceAndItsCreases) {
  for (const SurfaceInfo& info : surfaceCatalog()) {
    SCOPED_TRACE(info.name);
    FoldSession session(makeSurface(info.name, {{"resolution", 24}}));
    const Sheet& initial = session.initial();
    const PlanarSimplification flat = simplifyPlanar(initial);
    testing::expectInvariants(flat.sheet, initial);
    EXPECT_LT(flat.sheet.triangleCount() * 3, initial.triangleCount());
    expectSameSurface(flat.sheet, initial);
    EXPECT_NEAR(taggedLength(flat.sheet, EdgeKind::Slit), taggedLength(initial, EdgeKind::Slit),
                1e-9);

    // Grab the vertex farthest from the centroid and swing it a fifth of the size sideways.
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& p : initial.positions) centre += p;
    centre /= double(initial.vertexCount());
    VertexIndex far = 0;
    for (VertexIndex v = 0; v < initial.vertexCount(); ++v)
      if (glm::distance(initial.positions[v], centre) >
          glm::distance(initial.positions[far], centre))
        far = v;
    const glm::dvec3 grabbed = session.beginDragNear(initial.positions[far]);
    session.updateDrag(grabbed + 0.2 * sheetSize(initial) * glm::normalize(centre - grabbed) +
                       glm::dvec3(0.0, 0.0, 0.03));
    ASSERT_TRUE(session.commit());
    const PlanarSimplification folded = simplifyPlanar(session.fixed());
    testing::expectInvariants(folded.sheet, initial);
    EXPECT_LT(folded.sheet.triangleCount(), session.fixed().triangleCount());
    expectSameSurface(folded.sheet, session.fixed());
    EXPECT_GT(taggedLength(session.fixed(), EdgeKind::Crease), 0.0);
    EXPECT_NEAR(taggedLength(folded.sheet, EdgeKind::Crease),
                taggedLength(session.fixed(), EdgeKind::Crease), 1e-9);
  }
}

// The triangles drawn tinted are the reflected part: each coarse reflected triangle's centroid
// lies in a reflected triangle of the session, and each unreflected one's in an unreflected one.
void expectSameReflectedPart(const DisplaySession& display, const FoldSession& session) {
  const Sheet& coarse = display.sheet();
  const std::set<TriangleIndex> fine(session.reflectedTriangles().begin(),
                                     session.reflectedTriangles().end());
  const std::set<TriangleIndex> shown(display.reflectedTriangles().begin(),
                                      display.reflectedTriangles().end());
  for (TriangleIndex t = 0; t < coarse.triangleCount(); ++t) {
    const Triangle& tri = coarse.triangles[t];
    const glm::dvec2 centroid =
        (coarse.development[tri[0]] + coarse.development[tri[1]] + coarse.development[tri[2]]) /
        3.0;
    const std::optional<SurfacePoint> point =
        locateDevelopmentPoint(session.current(), centroid, 1e-9);
    ASSERT_TRUE(point);
    EXPECT_EQ(shown.contains(t), fine.contains(point->triangle)) << "coarse triangle " << t;
  }
}

void expectFollows(const DisplaySession& display, const FoldSession& session) {
  EXPECT_NE(&display.shownSession(), &session) << "fell back to the session's own sheet";
  testing::expectInvariants(display.sheet(), session.initial());
  expectSameSurface(display.sheet(), session.current());
  expectSameReflectedPart(display, session);
  EXPECT_LT(display.sheet().triangleCount() * 3, session.current().triangleCount());
}

TEST(DisplaySession, FollowsDragsCommitsCancelsUndoAndRedo) {
  FoldSession session(makeSurface("cylinder", {{"resolution", 32}}));
  DisplaySession display;
  display.follow(session);
  expectFollows(display, session);
  const std::uint64_t built = display.generation();

  // A drag from the top rim, a frame per update; then its commit is made on the coarse sheet
  // (no new simplification).
  const glm::dvec3 grabbed = session.beginDragNear({0.03, 0.105, 0.03});
  for (int step = 1; step <= 5; ++step) {
    session.updateDrag(grabbed + glm::dvec3(-0.006 * step, -0.015 * step, 0.004 * step));
    display.follow(session);
    SCOPED_TRACE(step);
    expectFollows(display, session);
  }
  ASSERT_TRUE(session.commit());
  display.follow(session);
  expectFollows(display, session);
  EXPECT_EQ(display.generation(), built);

  // A second drag updated several times between frames, then cancelled.
  const glm::dvec3 second = session.beginDragNear({-0.045, -0.1, 0.0});
  session.updateDrag(second + glm::dvec3(0.01, 0.02, 0.0));
  session.updateDrag(second + glm::dvec3(0.02, 0.05, 0.01));
  display.follow(session);
  expectFollows(display, session);
  session.cancel();
  display.follow(session);
  expectFollows(display, session);
  EXPECT_EQ(display.generation(), built);

  // Undo and redo change the design otherwise: simplified afresh.
  ASSERT_TRUE(session.undo());
  display.follow(session);
  expectFollows(display, session);
  EXPECT_GT(display.generation(), built);
  ASSERT_TRUE(session.redo());
  display.follow(session);
  expectFollows(display, session);
}

// Issue 17: in a symmetric design the drawn (coarse) sheet previews a drag's images, and is the
// same surface as what the commit then makes; a session without the symmetry previews nothing.
TEST(DisplaySession, PreviewsASymmetricDragsImages) {
  const Sheet initial = makeSurface("cylinder");
  FoldSession session(initial);
  session.setSymmetry(parseSymmetry("rotational:6", initial));
  DisplaySession display;
  display.follow(session);
  session.beginDragNear({0.045, 0.105, 0.0});
  session.updateDrag({0.036, 0.1, 0.0});
  display.follow(session);
  ASSERT_TRUE(display.shownSession().previewingImages());
  EXPECT_FALSE(session.previewingImages());  // the fine sheet is not remade at every update
  EXPECT_LT(display.sheet().triangleCount() * 3, session.current().triangleCount());
  EXPECT_FALSE(display.reflectedTriangles().empty());
  const Sheet previewed = display.sheet();
  ASSERT_TRUE(session.commit());
  ASSERT_EQ(session.foldCount(), 6u);
  expectSameSurface(previewed, session.fixed());

  FoldSession plain(initial);
  DisplaySession plainDisplay;
  plainDisplay.follow(plain);
  plain.beginDragNear({0.045, 0.105, 0.0});
  plain.updateDrag({0.036, 0.1, 0.0});
  plainDisplay.follow(plain);
  EXPECT_FALSE(plainDisplay.shownSession().previewingImages());
}

TEST(DisplaySession, CatchesUpWithSeveralOperationsBetweenFrames) {
  FoldSession session(makeSurface("cone", {{"resolution", 40}}));
  DisplaySession display;
  display.follow(session);
  // Commit one fold and start the next drag before the display looks again.
  const glm::dvec3 a = session.beginDragNear({0.08, 0.0, 0.0});
  session.updateDrag(a + glm::dvec3(-0.03, 0.04, 0.01));
  display.follow(session);
  session.updateDrag(a + glm::dvec3(-0.04, 0.05, 0.02));
  ASSERT_TRUE(session.commit());
  const glm::dvec3 b = session.beginDragNear({-0.08, 0.0, 0.0});
  session.updateDrag(b + glm::dvec3(0.02, 0.03, 0.0));
  display.follow(session);
  expectFollows(display, session);
  ASSERT_TRUE(session.commit());
  display.follow(session);
  expectFollows(display, session);
  EXPECT_EQ(session.foldCount(), 2u);
}

}  // namespace
}  // namespace curvefold
