// Grabbing any point of the surface, not only a vertex (DESIGN.md 1): finding the point, and
// making it a vertex by splitting the triangle or edge it lies on.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

// A point on a triangle, by barycentric coordinates (summing to 1) of its three vertices.
struct SurfacePoint {
  TriangleIndex triangle = kNoIndex;
  glm::dvec3 barycentric{1.0 / 3.0};
};

glm::dvec3 positionOf(const Sheet& sheet, const SurfacePoint& point);
glm::dvec2 developmentOf(const Sheet& sheet, const SurfacePoint& point);

// The point of one triangle nearest to p in 3D.
SurfacePoint closestPointOnTriangle(const Sheet& sheet, TriangleIndex triangle,
                                    const glm::dvec3& p);

// The surface point nearest to p in 3D (brute force over the triangles; ties go to the lowest
// triangle index, so the answer is deterministic). The sheet must not be empty.
SurfacePoint closestSurfacePoint(const Sheet& sheet, const glm::dvec3& p);

// The triangle whose development contains q (within tolerance metres), choosing the most interior
// candidate, or nothing when q lies outside the development.
std::optional<SurfacePoint> locateDevelopmentPoint(const Sheet& sheet, const glm::dvec2& q,
                                                   double tolerance);

// Relative distance (of the sheet's size) within which a grabbed point snaps to an existing vertex
// or edge instead of making a sliver.
inline constexpr double kRelativeGrabSnap = 1e-6;

struct VertexInsertion {
  Sheet sheet;
  VertexIndex vertex = kNoIndex;  // the vertex at the point (new, or the one it snapped to)
};

// Makes the development point q a vertex: an existing vertex within snap distance, else a new
// vertex splitting the edge within snap distance (both of its triangles), else one splitting the
// triangle containing q into three. The 3D position is interpolated with the same barycentric
// coordinates, so it is exact. Throws InvalidSheet when q lies outside the development. Live grabs
// and replays go through this one function, so both give the same sheet bit for bit.
VertexInsertion insertVertexAt(const Sheet& sheet, const glm::dvec2& q);

// What an in-place insertion changed, so it can be taken back exactly.
struct InsertionUndo {
  std::size_t vertexCount = 0;  // before
  std::size_t triangleCount = 0;
  std::vector<std::pair<TriangleIndex, Triangle>> rewritten;  // old values, in rewrite order
  std::vector<TaggedEdge> tags;                               // old tags, when tagsChanged
  bool tagsChanged = false;
};

// insertVertexAt on the sheet itself (the same result bit for bit, without copying the sheet);
// `undo`, when given, records how to take it back with undoInsertion.
VertexIndex insertVertexInPlace(Sheet& sheet, const glm::dvec2& q, InsertionUndo* undo);
void undoInsertion(Sheet& sheet, const InsertionUndo& undo);

}  // namespace curvefold
