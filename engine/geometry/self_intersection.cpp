#include "engine/geometry/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace curvefold {

namespace {

using Corners = std::array<glm::dvec3, 3>;

Corners cornersOf(const Sheet& sheet, TriangleIndex t) {
  const Triangle& tri = sheet.triangles[t];
  return {sheet.positions[tri[0]], sheet.positions[tri[1]], sheet.positions[tri[2]]};
}

// Whether two triangles' bounding boxes meet (within the tolerance): most neighbours in a leaf
// pair do not, and this is far cheaper than classifying them.
bool boxesMeet(const Corners& a, const Corners& b, double tolerance) {
  for (int axis = 0; axis < 3; ++axis) {
    const double loA = std::min({a[0][axis], a[1][axis], a[2][axis]});
    const double hiA = std::max({a[0][axis], a[1][axis], a[2][axis]});
    const double loB = std::min({b[0][axis], b[1][axis], b[2][axis]});
    const double hiB = std::max({b[0][axis], b[1][axis], b[2][axis]});
    if (loA > hiB + tolerance || loB > hiA + tolerance) return false;
  }
  return true;
}

// Each triangle's bounding box, found once per sheet: most pairs a walk reaches stop at the box
// test, which then reads two boxes instead of copying and scanning six corners per pair.
struct TriangleBox {
  glm::dvec3 low{0.0}, high{0.0};
};

std::vector<TriangleBox> triangleBoxes(const Sheet& sheet) {
  std::vector<TriangleBox> boxes(sheet.triangleCount());
  for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t) {
    const Corners c = cornersOf(sheet, t);
    for (int axis = 0; axis < 3; ++axis) {
      boxes[t].low[axis] = std::min({c[0][axis], c[1][axis], c[2][axis]});
      boxes[t].high[axis] = std::max({c[0][axis], c[1][axis], c[2][axis]});
    }
  }
  return boxes;
}

// boxesMeet of the two triangles' corners, from their boxes.
bool boxesMeet(const TriangleBox& a, const TriangleBox& b, double tolerance) {
  for (int axis = 0; axis < 3; ++axis)
    if (a.low[axis] > b.high[axis] + tolerance || b.low[axis] > a.high[axis] + tolerance)
      return false;
  return true;
}

// Neighbours across an edge are the crease itself: their dihedral is the fold, never a crossing.
// Triangles sharing one corner are tested (the classifier excludes that corner): a fan folded
// past itself passes through the sheet beyond it.
bool shareEdge(const Triangle& a, const Triangle& b) {
  int shared = 0;
  for (VertexIndex u : a)
    for (VertexIndex v : b) shared += u == v;
  return shared >= 2;
}

// Signs of distances with those within the tolerance snapped to zero.
int signOf(double d, double tolerance) {
  return d > tolerance ? 1 : (d < -tolerance ? -1 : 0);
}

// Whether the interiors of two coplanar triangles overlap by more than the tolerance: no edge's
// normal (in the plane) separates them.
bool coplanarOverlap(const Corners& a, const Corners& b, const glm::dvec3& normal,
                     double tolerance) {
  for (const Corners* edges : {&a, &b})
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 axis = glm::cross(normal, (*edges)[(k + 1) % 3] - (*edges)[k]);
      const double length = glm::length(axis);
      if (length == 0.0) continue;
      double loA = INFINITY, hiA = -INFINITY, loB = INFINITY, hiB = -INFINITY;
      for (int i = 0; i < 3; ++i) {
        const double pa = glm::dot(axis, a[i]) / length, pb = glm::dot(axis, b[i]) / length;
        loA = std::min(loA, pa), hiA = std::max(hiA, pa);
        loB = std::min(loB, pb), hiB = std::max(hiB, pb);
      }
      if (hiA <= loB + tolerance || hiB <= loA + tolerance) return false;
    }
  return true;
}

// Where a triangle meets a plane it crosses (signs of both kinds among its corners): the segment's
// ends as points, from the crossing edges and the corners on the plane.
std::array<glm::dvec3, 2> cut(const Corners& corners, const std::array<double, 3>& distance,
                              const std::array<int, 3>& sign) {
  std::array<glm::dvec3, 2> ends{};
  int found = 0;
  for (int i = 0; i < 3 && found < 2; ++i) {
    const int j = (i + 1) % 3;
    if (sign[i] == 0) ends[found++] = corners[i];
    if (found < 2 && sign[i] * sign[j] < 0) {
      const double t = distance[i] / (distance[i] - distance[j]);
      ends[found++] = corners[i] + t * (corners[j] - corners[i]);
    }
  }
  return ends;
}

}  // namespace

TrianglePairKind classifyTrianglePair(const Corners& a, const Corners& b, double tolerance,
                                      glm::dvec3* crossing) {
  glm::dvec3 normalA = glm::cross(a[1] - a[0], a[2] - a[0]);
  glm::dvec3 normalB = glm::cross(b[1] - b[0], b[2] - b[0]);
  const double lengthA = glm::length(normalA), lengthB = glm::length(normalB);
  if (lengthA == 0.0 || lengthB == 0.0) return TrianglePairKind::Apart;  // validate() refuses
  normalA /= lengthA;
  normalB /= lengthB;
  std::array<double, 3> toA{}, toB{};  // b's corners from a's plane; a's from b's
  std::array<int, 3> signToA{}, signToB{};
  int positiveB = 0, negativeB = 0, positiveA = 0, negativeA = 0;
  for (int i = 0; i < 3; ++i) {
    toA[i] = glm::dot(normalA, b[i] - a[0]);
    signToA[i] = signOf(toA[i], tolerance);
    positiveB += signToA[i] > 0, negativeB += signToA[i] < 0;
    toB[i] = glm::dot(normalB, a[i] - b[0]);
    signToB[i] = signOf(toB[i], tolerance);
    positiveA += signToB[i] > 0, negativeA += signToB[i] < 0;
  }
  if ((positiveB == 0 && negativeB == 0) || (positiveA == 0 && negativeA == 0))
    return coplanarOverlap(a, b, normalA, tolerance) ? TrianglePairKind::Contact
                                                     : TrianglePairKind::Apart;
  // Interiors cross only where each triangle has corners strictly on both sides of the other. A
  // shared corner lies on both planes, so both cuts start there and overlap beyond it (by more
  // than the tolerance) only when the triangles pass through each other, not when they meet
  // only at it.
  if (positiveB == 0 || negativeB == 0 || positiveA == 0 || negativeA == 0)
    return TrianglePairKind::Apart;
  const glm::dvec3 line = glm::normalize(glm::cross(normalA, normalB));
  const std::array<glm::dvec3, 2> cutA = cut(a, toB, signToB), cutB = cut(b, toA, signToA);
  double loA = glm::dot(line, cutA[0]), hiA = glm::dot(line, cutA[1]);
  double loB = glm::dot(line, cutB[0]), hiB = glm::dot(line, cutB[1]);
  glm::dvec3 fromA = cutA[0], toward = cutA[1];
  if (loA > hiA) {
    std::swap(loA, hiA);
    std::swap(fromA, toward);
  }
  if (loB > hiB) std::swap(loB, hiB);
  const double low = std::max(loA, loB), high = std::min(hiA, hiB);
  if (high - low <= tolerance) return TrianglePairKind::Apart;
  if (crossing) {
    const double middle = 0.5 * (low + high);
    *crossing = hiA > loA ? fromA + (toward - fromA) * ((middle - loA) / (hiA - loA)) : fromA;
  }
  return TrianglePairKind::Intersect;
}

TriangleTree buildTriangleTree(const Sheet& sheet) {
  TriangleTree tree;
  const std::size_t n = sheet.triangleCount();
  tree.order.resize(n);
  std::vector<glm::dvec3> low(n), high(n), centre(n);
  for (TriangleIndex t = 0; t < n; ++t) {
    tree.order[t] = t;
    const Corners c = cornersOf(sheet, t);
    low[t] = glm::min(c[0], glm::min(c[1], c[2]));
    high[t] = glm::max(c[0], glm::max(c[1], c[2]));
    centre[t] = (c[0] + c[1] + c[2]) / 3.0;
  }
  if (n == 0) return tree;
  tree.nodes.reserve(n);
  tree.nodes.emplace_back();
  // Ranges still to split: (node, first, count).
  struct Range {
    std::uint32_t node, first, count;
  };
  std::vector<Range> pending{{0, 0, std::uint32_t(n)}};
  constexpr std::uint32_t kLeafSize = 8;
  while (!pending.empty()) {
    const Range range = pending.back();
    pending.pop_back();
    glm::dvec3 boxLow(INFINITY), boxHigh(-INFINITY), centreLow(INFINITY), centreHigh(-INFINITY);
    for (std::uint32_t k = range.first; k < range.first + range.count; ++k) {
      const TriangleIndex t = tree.order[k];
      boxLow = glm::min(boxLow, low[t]), boxHigh = glm::max(boxHigh, high[t]);
      centreLow = glm::min(centreLow, centre[t]), centreHigh = glm::max(centreHigh, centre[t]);
    }
    TriangleTree::Node& node = tree.nodes[range.node];
    node.low = boxLow;
    node.high = boxHigh;
    if (range.count <= kLeafSize) {
      node.first = range.first;
      node.count = range.count;
      continue;
    }
    const glm::dvec3 extent = centreHigh - centreLow;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t half = range.count / 2;
    auto begin = tree.order.begin() + range.first;
    std::nth_element(
        begin, begin + half, begin + range.count,
        [&](TriangleIndex s, TriangleIndex t) { return centre[s][axis] < centre[t][axis]; });
    const std::uint32_t left = std::uint32_t(tree.nodes.size());
    node.first = left;
    node.count = 0;
    tree.nodes.emplace_back();
    tree.nodes.emplace_back();
    pending.push_back({left, range.first, half});
    pending.push_back({left + 1, range.first + half, range.count - half});
  }
  return tree;
}

namespace {

bool overlaps(const glm::dvec3& lowA, const glm::dvec3& highA, const glm::dvec3& lowB,
              const glm::dvec3& highB, double tolerance) {
  return lowA.x <= highB.x + tolerance && lowB.x <= highA.x + tolerance &&
         lowA.y <= highB.y + tolerance && lowB.y <= highA.y + tolerance &&
         lowA.z <= highB.z + tolerance && lowB.z <= highA.z + tolerance;
}

double spread(const TriangleTree::Node& node) {
  const glm::dvec3 e = node.high - node.low;
  return e.x + e.y + e.z;
}

void finish(const Sheet& sheet, double tolerance, SelfIntersectionReport& report) {
  std::sort(report.intersections.begin(), report.intersections.end());
  std::sort(report.contacts.begin(), report.contacts.end());
  if (!report.intersections.empty()) {
    const auto [s, t] = report.intersections.front();
    classifyTrianglePair(cornersOf(sheet, s), cornersOf(sheet, t), tolerance, &report.firstPoint);
  }
}

bool shareVertex(const Triangle& a, const Triangle& b) {
  for (VertexIndex u : a)
    for (VertexIndex v : b)
      if (u == v) return true;
  return false;
}

void record(const Sheet& sheet, const std::vector<TriangleBox>& boxes, TriangleIndex s,
            TriangleIndex t, double tolerance, SelfIntersectionReport& report) {
  if (shareEdge(sheet.triangles[s], sheet.triangles[t])) return;
  if (!boxesMeet(boxes[s], boxes[t], tolerance)) return;
  const TrianglePairKind kind =
      classifyTrianglePair(cornersOf(sheet, s), cornersOf(sheet, t), tolerance);
  if (kind == TrianglePairKind::Apart) return;
  auto& list = kind == TrianglePairKind::Intersect ? report.intersections : report.contacts;
  list.emplace_back(std::min(s, t), std::max(s, t));
}

// The vertices every triangle under a node has (at most three; none for most inner nodes), per
// node: the triangles of a fan all have its centre, and two nodes that share such a vertex hold
// only pairs that share it, which the star pass tests. Children follow their parents in the
// array, so one backward pass fills the inner nodes.
struct CommonVertices {
  std::array<VertexIndex, 3> vertices{};
  std::uint32_t count = 0;
  bool has(VertexIndex v) const {
    for (std::uint32_t k = 0; k < count; ++k)
      if (vertices[k] == v) return true;
    return false;
  }
  bool meets(const CommonVertices& other) const {
    for (std::uint32_t k = 0; k < count; ++k)
      if (other.has(vertices[k])) return true;
    return false;
  }
  CommonVertices within(const CommonVertices& other) const {
    CommonVertices both;
    for (std::uint32_t k = 0; k < count; ++k)
      if (other.has(vertices[k])) both.vertices[both.count++] = vertices[k];
    return both;
  }
};

std::vector<CommonVertices> commonVertices(const Sheet& sheet, const TriangleTree& tree) {
  std::vector<CommonVertices> common(tree.nodes.size());
  for (std::size_t k = tree.nodes.size(); k-- > 0;) {
    const TriangleTree::Node& node = tree.nodes[k];
    if (node.count == 0) {
      common[k] = common[node.first].within(common[node.first + 1]);
      continue;
    }
    const Triangle& first = sheet.triangles[tree.order[node.first]];
    common[k] = {{first[0], first[1], first[2]}, 3};
    for (std::uint32_t i = node.first + 1; i < node.first + node.count && common[k].count > 0;
         ++i) {
      const Triangle& t = sheet.triangles[tree.order[i]];
      common[k] = common[k].within({{t[0], t[1], t[2]}, 3});
    }
  }
  return common;
}

// Stars this small test every pair of their triangles.
constexpr std::size_t kSmallStar = 16;

// The pairs of triangles that share exactly one vertex, star by star. Near their shared vertex v
// two such triangles are wedges from v, and they cross or touch only along directions from v
// that both wedges hold (within the tolerance, an angle of about tolerance / edge length): each
// wedge's directions are an arc on the unit sphere, and only pairs whose arcs' boxes meet are
// classified. A fan of n triangles costs about n log n, not n^2.
void recordStars(const Sheet& sheet, const std::vector<TriangleBox>& boxes, double tolerance,
                 SelfIntersectionReport& report) {
  const std::size_t n = sheet.vertexCount();
  std::vector<std::uint32_t> start(n + 1, 0);
  for (const Triangle& t : sheet.triangles)
    for (VertexIndex v : t) ++start[v.value + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<TriangleIndex> star(start[n]);
  std::vector<std::uint32_t> filled(start.begin(), start.end() - 1);
  for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t)
    for (VertexIndex v : sheet.triangles[t]) star[filled[v.value]++] = t;

  struct Arc {
    glm::dvec3 low, high;
    TriangleIndex triangle;
  };
  std::vector<Arc> arcs;
  for (std::size_t v = 0; v < n; ++v) {
    const std::uint32_t first = start[v], count = start[v + 1] - start[v];
    if (count <= kSmallStar) {
      for (std::uint32_t i = first; i < first + count; ++i)
        for (std::uint32_t j = i + 1; j < first + count; ++j)
          record(sheet, boxes, star[i], star[j], tolerance, report);
      continue;
    }
    const glm::dvec3 centre = sheet.positions[v];
    arcs.clear();
    for (std::uint32_t i = first; i < first + count; ++i) {
      const Triangle& t = sheet.triangles[star[i]];
      const int k = t[0].value == v ? 0 : (t[1].value == v ? 1 : 2);
      const glm::dvec3 a = sheet.positions[t[(k + 1) % 3]] - centre;
      const glm::dvec3 b = sheet.positions[t[(k + 2) % 3]] - centre;
      const double la = glm::length(a), lb = glm::length(b);
      if (!(la > 0.0 && lb > 0.0)) {  // degenerate (validate() refuses it): every pair is tested
        arcs.push_back({glm::dvec3(-2.0), glm::dvec3(2.0), star[i]});
        continue;
      }
      const glm::dvec3 ua = a / la, ub = b / lb;
      // The arc bulges from its chord by at most 1 - cos(angle / 2); the tolerance is an angle of
      // tolerance / length at the nearer corner (doubled: the other wedge's share).
      const double cosHalf = std::sqrt(std::max(0.0, 0.5 * (1.0 + glm::dot(ua, ub))));
      const double margin = (1.0 - cosHalf) + 2.0 * tolerance / std::min(la, lb) + 1e-12;
      arcs.push_back({glm::min(ua, ub) - margin, glm::max(ua, ub) + margin, star[i]});
    }
    // Sweep along the axis the arcs spread most on.
    glm::dvec3 lowCentre(INFINITY), highCentre(-INFINITY);
    for (const Arc& arc : arcs) {
      lowCentre = glm::min(lowCentre, arc.low + arc.high);
      highCentre = glm::max(highCentre, arc.low + arc.high);
    }
    const glm::dvec3 extent = highCentre - lowCentre;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    std::sort(arcs.begin(), arcs.end(),
              [axis](const Arc& p, const Arc& q) { return p.low[axis] < q.low[axis]; });
    for (std::size_t i = 0; i < arcs.size(); ++i)
      for (std::size_t j = i + 1; j < arcs.size() && arcs[j].low[axis] <= arcs[i].high[axis]; ++j)
        if (overlaps(arcs[i].low, arcs[i].high, arcs[j].low, arcs[j].high, 0.0))
          record(sheet, boxes, arcs[i].triangle, arcs[j].triangle, tolerance, report);
  }
}

}  // namespace

// Pairs that share a vertex are the star pass's; the tree's walk tests the rest, and skips node
// pairs whose triangles all share one vertex (a fan's nodes, whose boxes all hold its centre).
SelfIntersectionReport findSelfIntersections(const Sheet& sheet) {
  SelfIntersectionReport report;
  const double tolerance = kRelativeContactTolerance * sheetSize(sheet);
  const std::vector<TriangleBox> boxes = triangleBoxes(sheet);
  recordStars(sheet, boxes, tolerance, report);
  const TriangleTree tree = buildTriangleTree(sheet);
  if (tree.nodes.empty()) {
    finish(sheet, tolerance, report);
    return report;
  }
  const std::vector<CommonVertices> common = commonVertices(sheet, tree);
  auto recordApart = [&](TriangleIndex s, TriangleIndex t) {
    if (!shareVertex(sheet.triangles[s], sheet.triangles[t]))
      record(sheet, boxes, s, t, tolerance, report);
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const TriangleTree::Node& A = tree.nodes[a];
    const TriangleTree::Node& B = tree.nodes[b];
    if (common[a].meets(common[b])) continue;
    if (a == b) {
      if (A.count > 0) {
        for (std::uint32_t i = A.first; i < A.first + A.count; ++i)
          for (std::uint32_t j = i + 1; j < A.first + A.count; ++j)
            recordApart(tree.order[i], tree.order[j]);
      } else {
        stack.push_back({A.first, A.first});
        stack.push_back({A.first + 1, A.first + 1});
        stack.push_back({A.first, A.first + 1});
      }
      continue;
    }
    if (!overlaps(A.low, A.high, B.low, B.high, tolerance)) continue;
    if (A.count > 0 && B.count > 0) {
      for (std::uint32_t i = A.first; i < A.first + A.count; ++i)
        for (std::uint32_t j = B.first; j < B.first + B.count; ++j)
          recordApart(tree.order[i], tree.order[j]);
    } else if (A.count > 0 || (B.count == 0 && spread(B) > spread(A))) {
      stack.push_back({a, B.first});
      stack.push_back({a, B.first + 1});
    } else {
      stack.push_back({A.first, b});
      stack.push_back({A.first + 1, b});
    }
  }
  finish(sheet, tolerance, report);
  return report;
}

SelfIntersectionReport findSelfIntersectionsBruteForce(const Sheet& sheet) {
  SelfIntersectionReport report;
  const double tolerance = kRelativeContactTolerance * sheetSize(sheet);
  const std::vector<TriangleBox> boxes = triangleBoxes(sheet);
  for (TriangleIndex s = 0; s < sheet.triangleCount(); ++s)
    for (TriangleIndex t = s + 1; t < sheet.triangleCount(); ++t)
      record(sheet, boxes, s, t, tolerance, report);
  finish(sheet, tolerance, report);
  return report;
}

void DragIntersectionWatch::begin(const Sheet& fixed) {
  tree_ = buildTriangleTree(fixed);
  tolerance_ = kRelativeContactTolerance * sheetSize(fixed);
  leafOf_.assign(fixed.triangleCount(), 0);
  for (std::uint32_t k = 0; k < tree_.nodes.size(); ++k)
    for (std::uint32_t i = tree_.nodes[k].first;
         tree_.nodes[k].count > 0 && i < tree_.nodes[k].first + tree_.nodes[k].count; ++i)
      leafOf_[tree_.order[i]] = k;
  splitStamp_.assign(fixed.triangleCount(), 0);
  nodeStamp_.assign(tree_.nodes.size(), 0);
  stamp_ = 0;
  active_ = true;
  pairCount_ = 0;
  triangles_.clear();
}

void DragIntersectionWatch::end() {
  active_ = false;
  pairCount_ = 0;
  triangles_.clear();
}

// The reflection's parts for the walk's node boxes: the plane, its normal's magnitudes (a box's
// reach across it) and the reflection's linear part (a box's reflected half-size).
struct DragIntersectionWatch::Mirror {
  const ReflectionPlane& plane;
  glm::dvec3 absN;
  glm::dmat3 linear;
};

void DragIntersectionWatch::update(const Sheet& folded, const ReflectionChanges& changes,
                                   const ReflectionPlane& plane,
                                   const std::vector<TriangleIndex>& reflected) {
  pairCount_ = 0;
  nodePairs_ = trianglePairs_ = 0;
  triangles_.clear();
  if (!active_ || tree_.nodes.empty() || reflected.empty()) return;
  moved_.assign(folded.triangleCount(), 0);
  for (TriangleIndex t : reflected) moved_[t] = 1;
  ++stamp_;
  listPieces(changes);
  markNodes(changes, reflected);
  const glm::dvec3 n = plane.normal;
  walk(folded, {plane, glm::abs(n), glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n)});
  std::sort(triangles_.begin(), triangles_.end());
  triangles_.erase(std::unique(triangles_.begin(), triangles_.end()), triangles_.end());
}

// The folded triangles each fixed one became: itself (kept or rewritten as a piece) and the
// pieces a cut appended, found through their origin. A cut triangle has pieces on both sides.
void DragIntersectionWatch::listPieces(const ReflectionChanges& changes) {
  pieces_.clear();
  for (std::size_t k = 0; k < changes.triangleOrigin.size(); ++k) {
    pieces_.emplace_back(changes.triangleOrigin[k],
                         TriangleIndex(std::uint32_t(changes.firstNewTriangle + k)));
    splitStamp_[changes.triangleOrigin[k]] = stamp_;
  }
  std::sort(pieces_.begin(), pieces_.end());
}

template <typename Visit>
void DragIntersectionWatch::forPieces(TriangleIndex t, Visit&& visit) const {
  visit(t);
  if (splitStamp_[t] != stamp_) return;
  auto it = std::lower_bound(pieces_.begin(), pieces_.end(), std::make_pair(t, TriangleIndex(0)));
  for (; it != pieces_.end() && it->first == t; ++it) visit(it->second);
}

// Per node of the tree, whether it holds a triangle with a reflected piece, and one with a piece
// left in place, from the reflected triangles alone (a leaf keeps a piece in place unless every
// triangle of it was reflected whole); children follow their parents in the array, so one
// backward pass fills the inner nodes.
void DragIntersectionWatch::markNodes(const ReflectionChanges& changes,
                                      const std::vector<TriangleIndex>& reflected) {
  hasMoved_.assign(tree_.nodes.size(), 0);
  hasRest_.assign(tree_.nodes.size(), 0);
  movedWhole_.assign(tree_.nodes.size(), 0);
  for (TriangleIndex t : reflected) {
    const TriangleIndex origin =
        t < changes.firstNewTriangle ? t : changes.triangleOrigin[t - changes.firstNewTriangle];
    const std::uint32_t leaf = leafOf_[origin];
    hasMoved_[leaf] = 1;
    if (splitStamp_[origin] == stamp_ || t >= changes.firstNewTriangle)
      hasRest_[leaf] = 1;
    else
      ++movedWhole_[leaf];
  }
  for (std::size_t k = tree_.nodes.size(); k-- > 0;) {
    const TriangleTree::Node& node = tree_.nodes[k];
    if (node.count > 0) {
      hasRest_[k] |= movedWhole_[k] < node.count;
      continue;
    }
    hasMoved_[k] = hasMoved_[node.first] | hasMoved_[node.first + 1];
    hasRest_[k] = hasRest_[node.first] | hasRest_[node.first + 1];
  }
}

// Per node, when the walk first meets it (a few thousand of a 100k-triangle tree's nodes):
// whether it can hold a reflected piece (some moved triangle, and a box that reaches the seed's
// side, d < 0, where the reflected part was) or a piece of the rest that can be met (some
// staying triangle, and a box that reaches beyond the plane, where the reflected part is now);
// and the box of its reflection (the reflection's linear part on its half-size).
void DragIntersectionWatch::meet(std::uint32_t k, const Mirror& mirror) {
  if (nodeStamp_[k] == stamp_) return;
  nodeStamp_[k] = stamp_;
  const TriangleTree::Node& node = tree_.nodes[k];
  const glm::dvec3 centre = 0.5 * (node.low + node.high), half = 0.5 * (node.high - node.low);
  const double d = mirror.plane.signedDistance(centre), reach = glm::dot(mirror.absN, half);
  hasMoved_[k] &= d - reach <= tolerance_;
  hasRest_[k] &= d + reach >= -tolerance_;
  if (!hasMoved_[k]) return;
  glm::dvec3 halfReflected(0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) halfReflected[i] += std::abs(mirror.linear[j][i]) * half[j];
  const glm::dvec3 centreReflected = mirror.plane.reflect(centre);
  reflectedLow_[k] = centreReflected - halfReflected;
  reflectedHigh_[k] = centreReflected + halfReflected;
}

// The tree against its own mirror image: node pairs (reflected part, rest) whose boxes meet, down
// to leaf pairs.
void DragIntersectionWatch::walk(const Sheet& folded, const Mirror& mirror) {
  reflectedLow_.resize(tree_.nodes.size());
  reflectedHigh_.resize(tree_.nodes.size());
  meet(0, mirror);
  stack_.assign(1, {0, 0});
  while (!stack_.empty()) {
    const auto [a, b] = stack_.back();
    stack_.pop_back();
    ++nodePairs_;
    if (!hasMoved_[a] || !hasRest_[b]) continue;
    const TriangleTree::Node& A = tree_.nodes[a];
    const TriangleTree::Node& B = tree_.nodes[b];
    if (!overlaps(reflectedLow_[a], reflectedHigh_[a], B.low, B.high, tolerance_)) continue;
    if (A.count > 0 && B.count > 0)
      testLeaves(folded, A, B);
    else
      splitNodePair(a, b, mirror);
  }
}

// Both sides split where they can, a child pair kept only if it can meet.
void DragIntersectionWatch::splitNodePair(std::uint32_t a, std::uint32_t b, const Mirror& mirror) {
  const TriangleTree::Node& A = tree_.nodes[a];
  const TriangleTree::Node& B = tree_.nodes[b];
  const std::uint32_t as[2] = {A.count > 0 ? a : A.first, A.count > 0 ? a : A.first + 1};
  const std::uint32_t bs[2] = {B.count > 0 ? b : B.first, B.count > 0 ? b : B.first + 1};
  for (int i = 0; i < (A.count > 0 ? 1 : 2); ++i) meet(as[i], mirror);
  for (int j = 0; j < (B.count > 0 ? 1 : 2); ++j) meet(bs[j], mirror);
  for (int i = 0; i < (A.count > 0 ? 1 : 2); ++i)
    for (int j = 0; j < (B.count > 0 ? 1 : 2); ++j)
      if (hasMoved_[as[i]] && hasRest_[bs[j]] &&
          overlaps(reflectedLow_[as[i]], reflectedHigh_[as[i]], tree_.nodes[bs[j]].low,
                   tree_.nodes[bs[j]].high, tolerance_))
        stack_.push_back({as[i], bs[j]});
}

// Leaf A's reflected pieces, where they are now, against leaf B's pieces left in place. The pair
// test stays in the loop: as a function of its own it was not inlined, and cost 5% more
// instructions per update (callgrind, bench_drag's 100k-triangle watches).
void DragIntersectionWatch::testLeaves(const Sheet& folded, const TriangleTree::Node& A,
                                       const TriangleTree::Node& B) {
  for (std::uint32_t i = A.first; i < A.first + A.count; ++i)
    forPieces(tree_.order[i], [&](TriangleIndex s) {
      if (!moved_[s]) return;
      // The reflected piece against the rest's node box first.
      const Corners cs = cornersOf(folded, s);
      const glm::dvec3 low = glm::min(cs[0], glm::min(cs[1], cs[2]));
      const glm::dvec3 high = glm::max(cs[0], glm::max(cs[1], cs[2]));
      if (!overlaps(low, high, B.low, B.high, tolerance_)) return;
      for (std::uint32_t j = B.first; j < B.first + B.count; ++j)
        forPieces(tree_.order[j], [&](TriangleIndex t) {
          if (moved_[t] || shareEdge(folded.triangles[s], folded.triangles[t])) return;
          const Corners ct = cornersOf(folded, t);
          if (!boxesMeet(cs, ct, tolerance_)) return;
          ++trianglePairs_;
          if (classifyTrianglePair(cs, ct, tolerance_) != TrianglePairKind::Intersect) return;
          ++pairCount_;
          triangles_.push_back(s);
          triangles_.push_back(t);
        });
    });
}

}  // namespace curvefold
