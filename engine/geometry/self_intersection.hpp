// Self-intersections of a folded sheet (issue 17, docs/design.md 7b). Mitani & Igarashi's system
// "does not check for self collisions" (Sec. 6): a design may pass through itself and still look
// finished, yet cannot be folded from paper. Two triangles intersect when they share no edge and
// their interiors cross (each has vertices strictly on both sides of the other's plane and the two
// cuts overlap along the planes' common line, by more than the tolerance). Triangles sharing one
// vertex are tested too, that vertex excluded: both cuts start at it, so they cross only when one
// passes through the other beyond it. Neighbours across an edge are the crease and never tested.
// Layers that only touch (coplanar within the tolerance, overlapping in area: a flat fold, with or
// without a shared vertex) are contact, counted apart.
//
// The tests run on a bounding-volume hierarchy of the sheet's triangles (flat arrays, built by
// median splits): the whole sheet against itself for `check` (pairs that share a vertex apart,
// star by star, by the directions their wedges span from it: a fan's triangles all share its
// centre, so their boxes all meet, and a box test alone made `check` quadratic on fans), and while
// dragging the reflected part against the rest on a tree of the sheet built once when the drag
// starts (DragIntersectionWatch): the reflected part is the reflection of its place in that sheet,
// so the tree is walked against its own mirror image and nothing is rebuilt per update.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/reflection.hpp"
#include "engine/geometry/sheet.hpp"

namespace curvefold {

enum class TrianglePairKind { Apart, Contact, Intersect };

// Two triangles (by their corners) against each other; `tolerance` in metres. They may share one
// corner (it is on both planes, and meeting only there is Apart); neighbours sharing an edge are
// the caller's to rule out (they always touch).
TrianglePairKind classifyTrianglePair(const std::array<glm::dvec3, 3>& a,
                                      const std::array<glm::dvec3, 3>& b, double tolerance,
                                      glm::dvec3* crossing = nullptr);

struct SelfIntersectionReport {
  // Intersecting and touching pairs, each (lower, higher) triangle index, sorted.
  std::vector<std::pair<TriangleIndex, TriangleIndex>> intersections, contacts;
  // A point on the first intersecting pair (on both triangles, within the tolerance).
  glm::dvec3 firstPoint{0.0};
};

// Every pair of the sheet's triangles that intersect or touch.
SelfIntersectionReport findSelfIntersections(const Sheet& sheet);

// Every pair by testing all pairs: the reference the tree is tested against (small sheets only).
SelfIntersectionReport findSelfIntersectionsBruteForce(const Sheet& sheet);

// A bounding-volume hierarchy over a sheet's triangles: nodes in one array, each leaf a range of
// `order`.
struct TriangleTree {
  struct Node {
    glm::dvec3 low{0.0}, high{0.0};
    std::uint32_t first = 0;  // leaf: first index into order; inner: left child (right = +1)
    std::uint32_t count = 0;  // leaf: triangles; inner: 0
  };
  std::vector<Node> nodes;
  std::vector<TriangleIndex> order;
};
TriangleTree buildTriangleTree(const Sheet& sheet);

// The live test of a drag: which triangles of the reflected part cross the rest. begin() builds
// the tree on the sheet the drag folds (its fixed sheet, grab vertex included); update() after
// each drag update takes the folded sheet, what the reflection changed and which triangles it
// reflected. Pairs within the reflected part, or within the rest, are as they were before the
// drag and are not looked at.
class DragIntersectionWatch {
 public:
  void begin(const Sheet& fixed);
  void update(const Sheet& folded, const ReflectionChanges& changes, const ReflectionPlane& plane,
              const std::vector<TriangleIndex>& reflected);
  // After a commit or cancel: nothing is watched.
  void end();

  bool active() const { return active_; }
  std::size_t pairCount() const { return pairCount_; }
  // Triangles of the folded sheet in an intersecting pair, sorted, each once.
  const std::vector<TriangleIndex>& triangles() const { return triangles_; }
  // The last update's work: pairs of tree nodes visited, pairs of triangles classified.
  std::size_t nodePairsVisited() const { return nodePairs_; }
  std::size_t trianglePairsTested() const { return trianglePairs_; }

 private:
  struct Mirror;
  // update()'s steps, in order.
  void listPieces(const ReflectionChanges& changes);
  void markNodes(const ReflectionChanges& changes, const std::vector<TriangleIndex>& reflected);
  void walk(const Sheet& folded, const Mirror& mirror);
  void meet(std::uint32_t k, const Mirror& mirror);
  void splitNodePair(std::uint32_t a, std::uint32_t b, const Mirror& mirror);
  void testLeaves(const Sheet& folded, const TriangleTree::Node& a, const TriangleTree::Node& b);
  // Visits fixed triangle `t`'s folded triangles: itself and the pieces a cut appended.
  template <typename Visit>
  void forPieces(TriangleIndex t, Visit&& visit) const;

  std::size_t nodePairs_ = 0, trianglePairs_ = 0;
  bool active_ = false;
  TriangleTree tree_;
  double tolerance_ = 0.0;
  std::size_t pairCount_ = 0;
  std::vector<TriangleIndex> triangles_;
  std::vector<std::uint8_t> moved_;               // per folded triangle: in the reflected part
  std::vector<std::uint8_t> hasMoved_, hasRest_;  // per tree node
  std::vector<glm::dvec3> reflectedLow_, reflectedHigh_;  // per tree node: its mirror's box
  std::vector<std::uint32_t> leafOf_;                     // per fixed triangle: its leaf
  std::vector<std::uint32_t> splitStamp_;  // per fixed triangle: == stamp_ when cut in pieces
  std::vector<std::uint32_t> movedWhole_;  // per leaf: its triangles reflected whole
  std::vector<std::uint32_t> nodeStamp_;   // per node: == stamp_ when the walk has met it
  std::uint32_t stamp_ = 0;
  // Per update, kept for their capacity: (fixed triangle, piece a cut appended) sorted, and the
  // walk's node pairs still to visit.
  std::vector<std::pair<TriangleIndex, TriangleIndex>> pieces_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack_;
};

}  // namespace curvefold
