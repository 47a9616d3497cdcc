// One reflection fold: Mitani & Igarashi, "Interactive Design of Planar Curved Folding by
// Reflection", Pacific Graphics 2011, Sec. 3.3 (DESIGN.md 2).
//
// The part of the sheet that contains the seed vertex, found by a flood fill that passes between
// triangles only through vertices strictly on the seed's side of the plane, is reflected through
// the plane; reached triangles the plane crosses are split along it, with one shared vertex per
// cut edge. Triangles the plane crosses but the fill never reaches are left alone [Fig. 3].
#pragma once

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
  std::vector<TriangleIndex> reflectedTriangles;  // every triangle of the reflected part
  std::vector<TriangleIndex> triangleOrigin;      // new triangles: the input triangle split
  std::size_t newCreaseCount = 0;
  bool splitAny = false;  // false: the whole reached part was mirrored without a cut
};

// Reusable buffers and the in-place form used while dragging: `out` must equal `sheet` except for
// what the previous call changed, which restore() puts back first. Results are identical to
// reflect() bit for bit.
class ReflectionWorkspace {
 public:
  // Applies the fold to `out` (which equals `sheet`) and records the changes.
  void apply(const Sheet& sheet, const VertexTriangles& adjacency, VertexIndex seed,
             const ReflectionPlane& plane, double epsilon, Sheet& out);
  // Puts `out` back to `sheet` by undoing the last apply() (cost proportional to what changed).
  void restore(const Sheet& sheet, Sheet& out) const;
  // Forgets the last apply(), for when `out` has been reset to `sheet` by other means.
  void clear();

  const ReflectionChanges& changes() const { return changes_; }

 private:
  // Per-vertex scratch in one record so the fill touches one cache line per vertex.
  struct VertexState {
    double distance = 0.0;  // signed distance, valid when distanceStamp == stamp_
    std::uint32_t distanceStamp = 0;
    std::uint32_t reachedStamp = 0;  // == stamp_: a strictly-negative vertex of the fill
  };

  void resize(std::size_t vertexCount, std::size_t triangleCount);
  void fill(const Sheet& sheet, const VertexTriangles& adjacency, VertexIndex seed,
            const ReflectionPlane& plane, double epsilon, Sheet& out);
  double distanceOf(const Sheet& sheet, const ReflectionPlane& plane, VertexIndex v);

  ReflectionChanges changes_;
  std::uint32_t stamp_ = 0;
  std::vector<VertexState> vertices_;
  std::vector<std::uint32_t> triangleReached_;  // == stamp_: triangle in the reached part
  std::vector<VertexIndex> reachedVertices_;
  std::vector<TriangleIndex> crossedTriangles_;  // reached, with vertices on both sides
  std::vector<TriangleIndex> hingeTriangles_;    // reached, not crossed, with an edge in the plane
  std::unordered_map<std::uint64_t, VertexIndex> cuts_;  // cut vertex of each split edge
  std::vector<Edge> splitEdges_;
  std::vector<TaggedEdge> newTags_;
  std::vector<TaggedEdge> keptTags_;
};

struct ReflectionResult {
  Sheet sheet;
  ReflectionChanges changes;
};

// Reflects the part containing `seed` through `plane`. epsilon: distances with |d| <= epsilon
// count as on the plane (sheetEpsilon(sheet) by default). If the seed itself is not strictly on the
// negative side, nothing is reflected and the sheet is returned unchanged.
ReflectionResult reflect(const Sheet& sheet, const VertexTriangles& adjacency, VertexIndex seed,
                         const ReflectionPlane& plane, double epsilon);
ReflectionResult reflect(const Sheet& sheet, VertexIndex seed, const ReflectionPlane& plane);

}  // namespace curvefold
