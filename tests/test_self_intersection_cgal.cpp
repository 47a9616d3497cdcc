// Self-intersections against CGAL (issue 28): the tree and its brute-force reference share the
// triangle-pair classifier, so they agree however it errs; CGAL's exact predicates are a reference
// of their own. On random folded designs (flat folds that lay layers on a square, folds through
// curved surfaces), every pair curvefold calls intersecting CGAL calls intersecting; every contact
// (coplanar layers) overlaps in the plane; and every pair CGAL calls intersecting that curvefold
// reports as neither only touches (shrunk a little, CGAL finds them apart). Pairs sharing one
// vertex are held to meeting beyond it.
#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, const Triangle3*>;
using Pair = std::pair<TriangleIndex, TriangleIndex>;

Point3 pointOf(const glm::dvec3& p) {
  return {p.x, p.y, p.z};
}

// The triangle shrunk toward its centroid by `by` of its size.
Triangle3 shrunk(const Sheet& sheet, TriangleIndex t, double by) {
  const Triangle& corners = sheet.triangles[t];
  const glm::dvec3 a = sheet.positions[corners[0]], b = sheet.positions[corners[1]],
                   c = sheet.positions[corners[2]];
  const glm::dvec3 centre = (a + b + c) / 3.0;
  auto in = [&](const glm::dvec3& p) { return pointOf(p + by * (centre - p)); };
  return {in(a), in(b), in(c)};
}

// Whether the two triangles, projected along the axis nearest the first one's normal, overlap.
bool overlapInPlane(const Sheet& sheet, TriangleIndex s, TriangleIndex t) {
  const Triangle& a = sheet.triangles[s];
  const glm::dvec3 normal = glm::abs(glm::cross(sheet.positions[a[1]] - sheet.positions[a[0]],
                                                sheet.positions[a[2]] - sheet.positions[a[0]]));
  const int drop =
      normal.x >= normal.y && normal.x >= normal.z ? 0 : (normal.y >= normal.z ? 1 : 2);
  auto projected = [&](TriangleIndex u) {
    std::array<Kernel::Point_2, 3> p;
    for (int i = 0; i < 3; ++i) {
      const glm::dvec3 q = sheet.positions[sheet.triangles[u][i]];
      p[i] = drop == 0 ? Kernel::Point_2(q.y, q.z)
                       : (drop == 1 ? Kernel::Point_2(q.z, q.x) : Kernel::Point_2(q.x, q.y));
    }
    return Kernel::Triangle_2(p[0], p[1], p[2]);
  };
  return CGAL::do_intersect(projected(s), projected(t));
}

// Every pair of triangles sharing no vertex that CGAL finds intersecting (touching included).
std::set<Pair> cgalPairs(const Sheet& sheet) {
  std::vector<Triangle3> triangles;
  triangles.reserve(sheet.triangleCount());
  for (const Triangle& t : sheet.triangles)
    triangles.emplace_back(pointOf(sheet.positions[t[0]]), pointOf(sheet.positions[t[1]]),
                           pointOf(sheet.positions[t[2]]));
  std::vector<Box> boxes;
  for (const Triangle3& t : triangles) boxes.emplace_back(t.bbox(), &t);
  std::set<Pair> pairs;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& p, const Box& q) {
    auto s = static_cast<TriangleIndex>(p.handle() - triangles.data());
    auto t = static_cast<TriangleIndex>(q.handle() - triangles.data());
    if (s > t) std::swap(s, t);
    for (VertexIndex u : sheet.triangles[s])
      for (VertexIndex v : sheet.triangles[t])
        if (u == v) return;
    if (CGAL::do_intersect(*p.handle(), *q.handle())) pairs.emplace(s, t);
  });
  return pairs;
}

// How many vertices triangles s and t share.
int sharedVertices(const Sheet& sheet, TriangleIndex s, TriangleIndex t) {
  int shared = 0;
  for (VertexIndex u : sheet.triangles[s])
    for (VertexIndex v : sheet.triangles[t]) shared += u == v;
  return shared;
}

// For triangles sharing one vertex: whether they meet beyond it. Past the shared vertex, the line
// where their planes cross leaves each triangle through the edge opposite that vertex, so they
// meet beyond it exactly when an opposite edge meets the other triangle.
bool cgalMeetBeyondTheSharedVertex(const Sheet& sheet, TriangleIndex s, TriangleIndex t) {
  auto opposite = [&](TriangleIndex u, TriangleIndex other) {
    std::vector<Point3> ends;
    for (VertexIndex v : sheet.triangles[u])
      if (std::find(sheet.triangles[other].begin(), sheet.triangles[other].end(), v) ==
          sheet.triangles[other].end())
        ends.push_back(pointOf(sheet.positions[v]));
    return Kernel::Segment_3(ends[0], ends[1]);
  };
  auto triangle = [&](TriangleIndex u) {
    const Triangle& c = sheet.triangles[u];
    return Triangle3(pointOf(sheet.positions[c[0]]), pointOf(sheet.positions[c[1]]),
                     pointOf(sheet.positions[c[2]]));
  };
  return CGAL::do_intersect(opposite(s, t), triangle(t)) ||
         CGAL::do_intersect(opposite(t, s), triangle(s));
}

TEST(SelfIntersection, AgreesWithCgalOnRandomFoldedDesigns) {
  std::mt19937 random(28);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t crossing = 0, layered = 0, touchingOnly = 0;
  for (const char* name : {"square", "square", "cylinder", "half_cylinder", "cone"}) {
    SCOPED_TRACE(name);
    FoldSession session(makeSurface(name, {{"resolution", 10}}));
    const double size = sheetSize(session.initial());
    const bool flat = std::string(name) == "square";
    for (int step = 0; step < 5; ++step) {
      const Sheet& fixed = session.fixed();
      const auto t = static_cast<TriangleIndex>(random() % fixed.triangleCount());
      const glm::dvec3 grabbed = session.beginDrag({t, {1.0 / 3, 1.0 / 3, 1.0 / 3}});
      // On the square, drags in its plane: flat folds, whose layers lie exactly in it.
      const glm::dvec3 move(unit(random), unit(random), flat ? 0.0 : unit(random));
      session.updateDrag(grabbed + 0.4 * size * move);
      session.commit();
      const Sheet& sheet = session.fixed();
      const SelfIntersectionReport report = findSelfIntersections(sheet);
      const std::set<Pair> cgal = cgalPairs(sheet);
      // Pairs sharing no vertex are compared both ways below; pairs sharing one vertex (tested
      // since the cone corner of issue 28, 2) are held to meeting beyond it.
      std::set<Pair> intersections, contacts;
      for (const Pair& p : report.intersections) {
        if (sharedVertices(sheet, p.first, p.second) == 0)
          intersections.insert(p);
        else
          EXPECT_TRUE(cgalMeetBeyondTheSharedVertex(sheet, p.first, p.second))
              << "step " << step << ": " << p.first << " " << p.second;
      }
      for (const Pair& p : report.contacts)
        if (sharedVertices(sheet, p.first, p.second) == 0) contacts.insert(p);
      for (const Pair& p : intersections)
        EXPECT_TRUE(cgal.count(p)) << "step " << step << ": " << p.first << " " << p.second;
      for (const Pair& p : contacts)
        EXPECT_TRUE(overlapInPlane(sheet, p.first, p.second))
            << "step " << step << ": " << p.first << " " << p.second;
      for (const Pair& p : cgal) {
        if (intersections.count(p) || contacts.count(p)) continue;
        ++touchingOnly;
        EXPECT_FALSE(
            CGAL::do_intersect(shrunk(sheet, p.first, 1e-6), shrunk(sheet, p.second, 1e-6)))
            << "step " << step << ": " << p.first << " " << p.second << " missed";
      }
      crossing += intersections.size();
      layered += contacts.size();
    }
  }
  // The designs held both kinds.
  EXPECT_GT(crossing, 0u);
  EXPECT_GT(layered, 0u);
  RecordProperty("touchingOnly", std::to_string(touchingOnly));
}

}  // namespace
}  // namespace curvefold
