// One reflection fold: Mitani & Igarashi, "Interactive Design of Planar Curved Folding by
// Reflection", Pacific Graphics 2011, Sec. 3.3 (docs/design.md 2).
//
// The part of the sheet that contains the seed vertex, found by a flood fill that passes between
// triangles only through vertices strictly on the seed's side of the plane, is reflected through
// the plane; reached triangles the plane crosses are split along it, with one shared vertex per
// cut edge. Triangles the plane crosses but the fill never reaches are left alone [Fig. 3].
#pragma once

#include <memory_resource>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/topology.hpp"

namespace curvefold {

// The plane d(x) = dot(x - point, normal) = 0, with a unit normal. The seed lies at d < 0.
struct ReflectionPlane {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};

  double signedDistance(const glm::dvec3& x) const;
  glm::dvec3 reflect(const glm::dvec3& x) const;
};

// The bisector plane of a drag from p0 to p1 (p0 != p1): normal (p1 - p0)/|p1 - p0| through the
// midpoint, so reflecting p0 gives p1.
ReflectionPlane bisectorPlane(const glm::dvec3& p0, const glm::dvec3& p1);

// What a reflection changed, in terms of the sheet it returned. Vertices and triangles below the
// input's counts keep their indices; new ones are appended.
struct ReflectionChanges {
  std::vector<VertexIndex> movedVertices;         // existing vertices whose position changed
  std::vector<TriangleIndex> rewrittenTriangles;  // existing triangles replaced by a sub-triangle
  std::size_t firstNewVertex = 0;                 // == input vertex count
  std::size_t firstNewTriangle = 0;               // == input triangle count
  std::vector<TriangleIndex> triangleOrigin;      // new triangles: the input triangle split
  std::size_t newCreaseCount = 0;
  bool splitAny = false;  // false: the whole reached part was mirrored without a cut
  // Metres the plane was moved along its normal so that no cut leaves a triangle thinner than the
  // minimum feature size (0: the plane as given).
  double planeShift = 0.0;
  // Smallest height of the triangles the cut made (infinity when nothing was cut).
  double thinnestCut = 0.0;
};

// How many planes are tried, each moved at most kRelativeMaxPlaneShift (tolerances.hpp).
inline constexpr int kMaxPlaneShiftTries = 8;

// Slivers: a plane that passes close to a vertex (just outside the on-plane tolerance) cuts the
// triangles around it into pieces thinner than kRelativeCutFeatureSize. The workspace then moves
// the plane along its normal to pass exactly through one of the vertices of those triangles
// (nearest first, within kRelativeMaxPlaneShift): that vertex lies on the plane and is not cut
// around. The result is still an exact reflection, and replaying the same plane moves it the same
// way. When no such plane helps, the least thin one is kept; a fold session refuses to commit a
// piece below the minimum feature size (none in 13,500 random folds: tests/soak.cpp).
//
// Reusable buffers and the in-place form used while dragging: `out` must equal `sheet` except for
// what the previous call changed, which restore() puts back first (or reapply() as it goes).
// Results are identical to reflect() bit for bit.
//
// The fill floods vertices, not triangles: only triangles around the boundary of the reached part
// are looked at (to split or hinge them), so the cost of an update is a few memory touches per
// reflected vertex. The list of reflected triangles, which only a renderer needs, is derived on
// request.
class ReflectionWorkspace {
 public:
  // Applies the fold to `out` (which equals `sheet`) and records the changes. The part also grows
  // from each of `moreSeeds` strictly on the seed's side: a symmetric fold's image whose part the
  // sheet's slit cuts in pieces (symmetry.hpp).
  void apply(const Sheet& sheet, const SheetAdjacency& adjacency, VertexIndex seed,
             const ReflectionPlane& plane, double epsilon, Sheet& out,
             std::span<const VertexIndex> moreSeeds = {});
  // Puts `out` back to `sheet` by undoing the last apply() (cost proportional to what changed).
  void restore(const Sheet& sheet, Sheet& out) const;
  // restore() then apply(), except that positions the new fold moves again are not first written
  // back: a drag moves mostly the same vertices frame after frame.
  void reapply(const Sheet& sheet, const SheetAdjacency& adjacency, VertexIndex seed,
               const ReflectionPlane& plane, double epsilon, Sheet& out);
  // Forgets the last apply(), for when `out` has been reset to `sheet` by other means.
  void clear();

  const ReflectionChanges& changes() const { return changes_; }
  std::size_t memoryBytes() const;
  // Every triangle of the last apply()'s result that lies in the reflected part (computed on the
  // first call after an apply; `adjacency` must be the one given to it).
  const std::vector<TriangleIndex>& reflectedTriangles(const SheetAdjacency& adjacency);

 private:
  // One reflection through `plane`, no snapping; records the pieces thinner than `feature`.
  void applyThrough(const Sheet& sheet, const SheetAdjacency& adjacency, VertexIndex seed,
                    const ReflectionPlane& plane, double epsilon, double feature, Sheet& out,
                    std::span<const VertexIndex> moreSeeds);
  void resize(std::size_t vertexCount, std::size_t triangleCount);
  void fill(const Sheet& sheet, const SheetAdjacency& adjacency, VertexIndex seed,
            const ReflectionPlane& plane, double epsilon, Sheet& out,
            std::span<const VertexIndex> moreSeeds);
  void classifyBoundary(const Sheet& sheet, const SheetAdjacency& adjacency, double epsilon);
  // applyThrough's steps after the fill: the creases on hinge edges, the crossed triangles
  // split, the result's tags.
  void tagHingeEdges(const Sheet& sheet, const SheetAdjacency& adjacency, double epsilon);
  void splitCrossedTriangles(const Sheet& sheet, const ReflectionPlane& plane, double epsilon,
                             double feature, Sheet& out);
  void mergeTags(const Sheet& sheet, Sheet& out);
  void restoreTopology(const Sheet& sheet, Sheet& out) const;
  // Marks of the current apply(): every visited vertex has at least visitedMark(); reached ones
  // (strictly on the seed's side, reflected) have reachedMark().
  std::uint32_t visitedMark() const { return 2 * stamp_; }
  std::uint32_t reachedMark() const { return 2 * stamp_ + 1; }
  bool reached(VertexIndex v) const { return vertexMarks_[v] == reachedMark(); }
  // Of a visited vertex: -1 reached (strictly on the seed's side), 0 on the plane, +1 beyond.
  int sideOf(VertexIndex v, double epsilon) const;

  ReflectionChanges changes_;
  std::vector<VertexIndex> previousMoved_;  // reapply(): what the last apply() moved
  std::uint32_t stamp_ = 0;
  // Per vertex, visitedMark() or more when its distance is known (the seed or a neighbour of a
  // reached vertex). Apart from the distances because the fill checks every neighbour of every
  // reached vertex but computes a distance once: a dense array of marks keeps those checks, and
  // the later "was it reached?" ones, in cache.
  std::vector<std::uint32_t> vertexMarks_;
  // Signed distance to the plane of each visited vertex that was not reached (only a cut needs a
  // reached vertex's distance, and recomputes it).
  std::vector<double> distances_;
  std::vector<std::uint32_t> triangleSeen_;      // == stamp_: classified by classifyBoundary
  std::vector<std::uint32_t> triangleCrossed_;   // == stamp_: split by the plane
  std::vector<std::uint32_t> triangleListed_;    // == listStamp_: in reflected_
  std::vector<VertexIndex> boundaryVertices_;    // visited, not reached: on or beyond the plane
  std::vector<TriangleIndex> crossedTriangles_;  // reached, with vertices on both sides
  std::vector<TriangleIndex> hingeTriangles_;    // reached, not crossed, with an edge in the plane
  std::vector<TriangleIndex> reflectedPieces_;   // sub-triangles on the reflected side
  std::vector<TriangleIndex> sliverSources_;     // input triangles cut into too thin pieces
  std::vector<double> triedShifts_;
  std::vector<TriangleIndex> reflected_;
  std::uint32_t listStamp_ = 0;
  bool reflectedReady_ = false;
  // Cut vertex of each split edge. Its nodes come from a buffer that is released, not freed node
  // by node, before each apply(): a drag makes hundreds of cuts a frame.
  std::pmr::monotonic_buffer_resource cutMemory_;
  std::optional<std::pmr::unordered_map<std::uint64_t, VertexIndex>> cuts_;
  std::vector<Edge> splitEdges_;
  std::vector<TaggedEdge> newTags_;
  std::vector<TaggedEdge> keptTags_;
};

struct ReflectionResult {
  Sheet sheet;
  ReflectionChanges changes;
  std::vector<TriangleIndex> reflectedTriangles;  // every triangle of the reflected part
};

// Reflects the part containing `seed` through `plane`. epsilon: distances with |d| <= epsilon
// count as on the plane (sheetEpsilon(sheet) by default). If the seed itself is not strictly on the
// negative side, nothing is reflected and the sheet is returned unchanged.
ReflectionResult reflect(const Sheet& sheet, const SheetAdjacency& adjacency, VertexIndex seed,
                         const ReflectionPlane& plane, double epsilon,
                         std::span<const VertexIndex> moreSeeds = {});
ReflectionResult reflect(const Sheet& sheet, VertexIndex seed, const ReflectionPlane& plane);

}  // namespace curvefold
