// Self-intersections (issue 17, 1): the triangle-pair test, the whole-sheet check on its tree
// against a brute-force all-pairs test on random designs, and the live drag watch against the
// pairs of the folded sheet that cross between the reflected part and the rest.
#include <cmath>
#include <random>
#include <tuple>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

using Corners = std::array<glm::dvec3, 3>;

TEST(TrianglePair, CrossingTouchingAndLyingFlat) {
  const Corners flat{glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)};
  const double tolerance = 1e-9;
  glm::dvec3 point;
  // Standing through the middle of the other.
  EXPECT_EQ(
      classifyTrianglePair(
          flat, {glm::dvec3(0.2, 0.2, -0.5), glm::dvec3(0.3, 0.2, 0.5), glm::dvec3(0.2, 0.3, 0.5)},
          tolerance, &point),
      TrianglePairKind::Intersect);
  EXPECT_NEAR(point.z, 0.0, 1e-12);
  EXPECT_GT(point.x, 0.0);
  EXPECT_GT(point.y, 0.0);
  // Standing on it (a corner on the face), and beside it: apart.
  EXPECT_EQ(
      classifyTrianglePair(
          flat, {glm::dvec3(0.2, 0.2, 0.0), glm::dvec3(0.3, 0.2, 0.5), glm::dvec3(0.2, 0.3, 0.5)},
          tolerance),
      TrianglePairKind::Apart);
  EXPECT_EQ(
      classifyTrianglePair(
          flat, {glm::dvec3(2.2, 0.2, -0.5), glm::dvec3(2.3, 0.2, 0.5), glm::dvec3(2.2, 0.3, 0.5)},
          tolerance),
      TrianglePairKind::Apart);
  // Through the plane but past the triangle's edge: apart.
  EXPECT_EQ(
      classifyTrianglePair(
          flat, {glm::dvec3(0.8, 0.8, -0.5), glm::dvec3(0.9, 0.8, 0.5), glm::dvec3(0.8, 0.9, 0.5)},
          tolerance),
      TrianglePairKind::Apart);
  // Lying on it (a flat fold's layers): contact; lying beside it, or just above: apart.
  EXPECT_EQ(classifyTrianglePair(flat,
                                 {glm::dvec3(0.1, 0.1, 1e-12), glm::dvec3(0.6, 0.1, 0.0),
                                  glm::dvec3(0.1, 0.6, -1e-12)},
                                 tolerance),
            TrianglePairKind::Contact);
  EXPECT_EQ(
      classifyTrianglePair(
          flat, {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(2.0, 0.0, 0.0), glm::dvec3(1.0, 1.0, 0.0)},
          tolerance),
      TrianglePairKind::Apart);
  EXPECT_EQ(classifyTrianglePair(flat,
                                 {glm::dvec3(0.1, 0.1, 1e-6), glm::dvec3(0.6, 0.1, 1e-6),
                                  glm::dvec3(0.1, 0.6, 1e-6)},
                                 tolerance),
            TrianglePairKind::Apart);
}

// Triangles sharing one corner (the origin): one passing through the other beyond it crosses;
// meeting only at it (a fan, folded or flat), or leaning on it along an edge, does not; lying on
// it and overlapping (a flat fold) is contact.
TEST(TrianglePair, SharingOneCornerCrossesOnlyBeyondIt) {
  const glm::dvec3 o(0.0);
  const Corners flat{o, glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)};
  const double tolerance = 1e-9;
  glm::dvec3 point;
  EXPECT_EQ(classifyTrianglePair(flat, {o, glm::dvec3(0.6, 0.2, 0.5), glm::dvec3(0.2, 0.6, -0.5)},
                                 tolerance, &point),
            TrianglePairKind::Intersect);
  EXPECT_NEAR(point.z, 0.0, 1e-12);
  EXPECT_GT(point.x, 0.1);  // off the shared corner, inside both
  EXPECT_NEAR(point.x, point.y, 1e-12);
  // The other's planes cross, but its cut runs away from the triangle: they meet at the corner.
  EXPECT_EQ(classifyTrianglePair(
                flat, {o, glm::dvec3(-0.6, -0.2, 0.5), glm::dvec3(-0.2, -0.6, -0.5)}, tolerance),
            TrianglePairKind::Apart);
  EXPECT_EQ(
      classifyTrianglePair(flat, {o, glm::dvec3(-1, 0, 0.3), glm::dvec3(0, -1, 0.3)}, tolerance),
      TrianglePairKind::Apart);
  EXPECT_EQ(classifyTrianglePair(flat, {o, glm::dvec3(0.3, 0.3, 0.0), glm::dvec3(0.3, 0.3, 1.0)},
                                 tolerance),
            TrianglePairKind::Apart);
  EXPECT_EQ(classifyTrianglePair(flat, {o, glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0)}, tolerance),
            TrianglePairKind::Apart);
  EXPECT_EQ(
      classifyTrianglePair(flat, {o, glm::dvec3(0.5, 0.1, 0), glm::dvec3(0.1, 0.5, 0)}, tolerance),
      TrianglePairKind::Contact);
}

// A sheet of two triangles sharing vertex 0 (the second's corners given), its development a
// fan of the same size.
Sheet twoTrianglesSharingACorner(const glm::dvec3& b1, const glm::dvec3& b2) {
  Sheet sheet;
  sheet.positions = {glm::dvec3(0.0), {1, 0, 0}, {0, 1, 0}, b1, b2};
  sheet.development = {{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  sheet.triangles = {{0, 1, 2}, {0, 3, 4}};
  return sheet;
}

// The whole-sheet check (tree and all pairs) tests pairs sharing one vertex.
TEST(SelfIntersection, PairsSharingOneVertexAreTested) {
  using Pairs = std::vector<std::pair<TriangleIndex, TriangleIndex>>;
  const Pairs pair{{0, 1}};
  for (const auto& [b1, b2, crossing, touching] :
       {std::tuple{glm::dvec3(0.6, 0.2, 0.5), glm::dvec3(0.2, 0.6, -0.5), true, false},
        std::tuple{glm::dvec3(-0.6, -0.2, 0.5), glm::dvec3(-0.2, -0.6, -0.5), false, false},
        std::tuple{glm::dvec3(0.5, 0.1, 0.0), glm::dvec3(0.1, 0.5, 0.0), false, true}}) {
    const Sheet sheet = twoTrianglesSharingACorner(b1, b2);
    for (const SelfIntersectionReport& report :
         {findSelfIntersections(sheet), findSelfIntersectionsBruteForce(sheet)}) {
      EXPECT_EQ(report.intersections, crossing ? pair : Pairs{});
      EXPECT_EQ(report.contacts, touching ? pair : Pairs{});
    }
  }
}

// Issue 40: a fan's triangles all share its centre, and `check` tests them star by star, by the
// directions their wedges span from it (no longer every pair: it was quadratic). Crumpled fans
// (rims at random heights and radii, wedges that overlap when their angles are jittered past each
// other, some lying flat on each other), each with a ring of triangles around it, agree with all
// pairs, crossings and contacts alike.
TEST(SelfIntersection, FansAgreeWithAllPairs) {
  std::mt19937_64 random(40);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t crossings = 0, contacts = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 20 + 40 * trial;  // stars from 20 to 460 triangles: past the small-star bound
    const double jitter = trial % 3 == 0 ? 0.0 : 3.0, lift = trial % 4 == 1 ? 0.0 : 0.02;
    Sheet sheet;
    sheet.positions.push_back({0.0, 0.0, 0.0});
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * 3.14159265358979 * (i + jitter * (unit(random) - 0.5)) / n;
      const double r = 0.1 * (0.5 + unit(random));
      sheet.positions.push_back({r * std::cos(a), r * std::sin(a), lift * (unit(random) - 0.5)});
    }
    for (int i = 0; i < n; ++i)  // the ring outside the fan
      sheet.positions.push_back(1.3 * sheet.positions[1 + i] +
                                glm::dvec3(0, 0, 0.01 * unit(random)));
    for (int i = 0; i < n; ++i) {
      const auto rim = [&](int k) { return VertexIndex(1 + (k % n)); };
      const auto outer = [&](int k) { return VertexIndex(1 + n + (k % n)); };
      sheet.triangles.push_back({VertexIndex(0), rim(i), rim(i + 1)});
      sheet.triangles.push_back({rim(i), outer(i), outer(i + 1)});
      sheet.triangles.push_back({rim(i), outer(i + 1), rim(i + 1)});
    }
    for (const glm::dvec3& p : sheet.positions) sheet.development.push_back({p.x, p.y});
    const SelfIntersectionReport tree = findSelfIntersections(sheet);
    const SelfIntersectionReport all = findSelfIntersectionsBruteForce(sheet);
    EXPECT_EQ(tree.intersections, all.intersections) << "trial " << trial;
    EXPECT_EQ(tree.contacts, all.contacts) << "trial " << trial;
    crossings += all.intersections.size();
    contacts += all.contacts.size();
  }
  // The fans hold both kinds, or the comparison says little.
  EXPECT_GT(crossings, 100u);
  EXPECT_GT(contacts, 50u);
}

// The reflection of a point through the plane with unit normal n through q.
glm::dvec3 mirrored(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& n) {
  return p - 2.0 * glm::dot(p - q, n) * n;
}

// Every pair of the folded sheet that crosses between the reflected part and the rest.
std::size_t crossingsBetweenParts(const FoldSession& session) {
  const Sheet& sheet = session.current();
  std::vector<std::uint8_t> moved(sheet.triangleCount(), 0);
  for (TriangleIndex t : session.reflectedTriangles()) moved[t] = 1;
  std::size_t count = 0;
  for (const auto& [s, t] : findSelfIntersectionsBruteForce(sheet).intersections)
    count += moved[s] != moved[t];
  return count;
}

// A truncated 300-degree cone of six triangles, its corner folded through the next panel
// (`curvefold new cone --angle 300 --top_radius 0.02 --resolution 3`, then `fold`): the crossing
// triangles share one vertex, and both the watch and `check` see them.
TEST(SelfIntersection, AConeCornerFoldedThroughTheTriangleBesideItIsFlagged) {
  FoldSession session(
      makeSurface("cone", {{"angle", 300.0}, {"top_radius", 0.02}, {"resolution", 3}}));
  ASSERT_TRUE(findSelfIntersections(session.fixed()).intersections.empty());
  session.beginDragNear({-0.01, 0.06, -0.017320508075688773});
  DragIntersectionWatch watch;
  watch.begin(session.fixed());
  session.updateDrag({0.04048325757935013, -0.06534938107471035, -0.07413437895813192});
  watch.update(session.current(), session.lastChanges(), session.plane(),
               session.reflectedTriangles());
  EXPECT_GT(watch.pairCount(), 0u);
  EXPECT_EQ(watch.pairCount(), crossingsBetweenParts(session));
  ASSERT_TRUE(session.commit());
  const Sheet& sheet = session.fixed();
  const SelfIntersectionReport report = findSelfIntersections(sheet);
  ASSERT_FALSE(report.intersections.empty());
  EXPECT_EQ(report.intersections, findSelfIntersectionsBruteForce(sheet).intersections);
  bool sharingOne = false;
  for (const auto& [s, t] : report.intersections) {
    int shared = 0;
    for (VertexIndex u : sheet.triangles[s])
      for (VertexIndex v : sheet.triangles[t]) shared += u == v;
    sharingOne |= shared == 1;
  }
  EXPECT_TRUE(sharingOne);
}

// A tube's top, folded down through a slanted plane into the tube and out through its far wall,
// crosses it; the watch sees it while dragging, and `check` after the commit.
TEST(SelfIntersection, ATubesFlapPushedThroughTheOppositeWallIsFlagged) {
  FoldSession session(makeSurface("cylinder", {{"resolution", 16}}));  // r 4.5 cm, y +-10.5 cm
  ASSERT_TRUE(findSelfIntersections(session.fixed()).intersections.empty());
  const glm::dvec3 normal = glm::normalize(glm::dvec3(-1.0, -1.0, 0.0));
  const glm::dvec3 through(0.0, 0.105 - 0.08, 0.0);
  const glm::dvec3 grabbed = session.beginDragNear({0.045, 0.1, 0.0});
  DragIntersectionWatch watch;
  watch.begin(session.fixed());
  session.updateDrag(mirrored(grabbed, through, normal));
  watch.update(session.current(), session.lastChanges(), session.plane(),
               session.reflectedTriangles());
  EXPECT_GT(watch.pairCount(), 0u);
  EXPECT_EQ(watch.pairCount(), crossingsBetweenParts(session));
  EXPECT_FALSE(watch.triangles().empty());
  ASSERT_TRUE(session.commit());
  const SelfIntersectionReport report = findSelfIntersections(session.fixed());
  EXPECT_EQ(report.intersections.size(), watch.pairCount());
  // The reported point lies on both triangles' planes.
  const auto [s, t] = report.intersections.front();
  for (TriangleIndex k : {s, t}) {
    const Triangle& tri = session.fixed().triangles[k];
    const glm::dvec3 a = session.fixed().positions[tri[0]];
    const glm::dvec3 n = glm::normalize(
        glm::cross(session.fixed().positions[tri[1]] - a, session.fixed().positions[tri[2]] - a));
    EXPECT_NEAR(glm::dot(report.firstPoint - a, n), 0.0, 1e-9);
  }
}

// A corner laid flat on the sheet (a 180-degree fold) touches it: contact, not an intersection;
// a corner lifted to stand in the air does neither.
TEST(SelfIntersection, AFlapLaidFlatIsContactAndALiftedOneIsNothing) {
  FoldSession session(makeSurface("square", {{"resolution", 10}}));
  session.beginDragNear({0.09, 0.09, 0.0});
  DragIntersectionWatch watch;
  watch.begin(session.fixed());
  session.updateDrag({0.03, 0.03, 0.0});
  watch.update(session.current(), session.lastChanges(), session.plane(),
               session.reflectedTriangles());
  EXPECT_EQ(watch.pairCount(), 0u);
  ASSERT_TRUE(session.commit());
  SelfIntersectionReport flat = findSelfIntersections(session.fixed());
  EXPECT_TRUE(flat.intersections.empty());
  EXPECT_GT(flat.contacts.size(), 0u);

  FoldSession lifted(makeSurface("square", {{"resolution", 10}}));
  lifted.beginDragNear({0.09, 0.09, 0.0});
  lifted.updateDrag({0.06, 0.06, 0.04});
  ASSERT_TRUE(lifted.commit());
  const SelfIntersectionReport air = findSelfIntersections(lifted.fixed());
  EXPECT_TRUE(air.intersections.empty());
  EXPECT_TRUE(air.contacts.empty());
}

// On random designs (up to about 2k triangles, random drags on every kind of surface, many of
// them through the sheet) the tree finds exactly the pairs the all-pairs test finds, and the
// watch exactly the crossings between the reflected part and the rest.
TEST(SelfIntersection, TheTreeAndTheWatchAgreeWithAllPairsOnRandomDesigns) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t intersecting = 0, touching = 0, watched = 0;
  for (const char* name : {"square", "cylinder", "half_cylinder", "cone", "star"}) {
    SCOPED_TRACE(name);
    FoldSession session(makeSurface(name, {{"resolution", 12}}));
    const double size = sheetSize(session.initial());
    for (int step = 0; step < 6; ++step) {
      const Sheet& fixed = session.fixed();
      const auto t = static_cast<TriangleIndex>(random() % fixed.triangleCount());
      const glm::dvec3 grabbed = session.beginDrag({t, {1.0 / 3, 1.0 / 3, 1.0 / 3}});
      DragIntersectionWatch watch;
      watch.begin(session.fixed());
      session.updateDrag(grabbed +
                         0.4 * size * glm::dvec3(unit(random), unit(random), unit(random)));
      watch.update(session.current(), session.lastChanges(), session.plane(),
                   session.reflectedTriangles());
      EXPECT_EQ(watch.pairCount(), crossingsBetweenParts(session)) << "step " << step;
      watched += watch.pairCount();
      session.commit();
      const SelfIntersectionReport tree = findSelfIntersections(session.fixed());
      const SelfIntersectionReport all = findSelfIntersectionsBruteForce(session.fixed());
      EXPECT_EQ(tree.intersections, all.intersections) << "step " << step;
      EXPECT_EQ(tree.contacts, all.contacts) << "step " << step;
      intersecting += all.intersections.size();
      touching += all.contacts.size();
      EXPECT_LE(session.fixed().triangleCount(), 2500u);
    }
  }
  // The designs exercised both kinds.
  EXPECT_GT(intersecting, 0u);
  EXPECT_GT(watched, 0u);
  RecordProperty("contacts", std::to_string(touching));
}

}  // namespace
}  // namespace curvefold
