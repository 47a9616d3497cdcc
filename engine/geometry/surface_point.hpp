// Grabbing any point of the surface, not only a vertex (docs/design.md 1): finding the point, and
// making it a vertex by splitting the triangle or edge it lies on.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/topology.hpp"

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

// How far from the sheet a point handed to a search or a drag may lie, in sheet sizes: far beyond
// any reach of a hand or a command, and far inside where squared distances overflow.
inline constexpr double kRelativeMaxReach = 1e6;

// Whether p (finite) lies within kRelativeMaxReach sheet sizes of `from` (a point of the sheet).
bool withinReach(const glm::dvec3& p, const glm::dvec3& from, double sheetSize);
// Throws InvalidSheet "<what> (x, y, z) lies too far from the sheet ..." when it does not, or
// "<what> (nan, 0, 0) is not a point ..." when a coordinate is not finite.
void checkWithinReach(const glm::dvec3& p, const glm::dvec3& from, double sheetSize,
                      const char* what);

// The surface point nearest to p in 3D (brute force over the triangles; ties go to the lowest
// triangle index, so the answer is deterministic). Never returns an invalid point: throws
// InvalidSheet for an empty sheet or a p farther than kRelativeMaxReach sheet sizes from it.
SurfacePoint closestSurfacePoint(const Sheet& sheet, const glm::dvec3& p);

// The triangle whose development contains q (within tolerance metres), choosing the most interior
// candidate, or nothing when q lies outside the development.
std::optional<SurfacePoint> locateDevelopmentPoint(const Sheet& sheet, const glm::dvec2& q,
                                                   double tolerance);

struct VertexInsertion {
  Sheet sheet;
  VertexIndex vertex = kNoIndex;  // the vertex at the point (new, or the one it snapped to)
};

// Makes the development point q a vertex: an existing vertex within snap distance, else a new
// vertex splitting the edge within snap distance (both of its triangles), else one splitting the
// triangle containing q into three. What it would make is never thinner than
// kRelativeCutFeatureSize: such a split takes the nearest vertex instead. The 3D position is
// interpolated with the same barycentric coordinates, so it is exact. Throws InvalidSheet when q
// lies outside the development. Live grabs and replays go through this one function, so both give
// the same sheet bit for bit.
VertexInsertion insertVertexAt(const Sheet& sheet, const glm::dvec2& q);

// The vertex at each development point (within kRelativeGrabSnap of the size). Throws InvalidSheet
// naming a point where the sheet has no vertex.
std::vector<VertexIndex> verticesAtDevelopment(const Sheet& sheet,
                                               const std::vector<glm::dvec2>& points);

// What an in-place insertion changed, so it can be taken back exactly.
struct InsertionUndo {
  std::size_t vertexCount = 0;  // before
  std::size_t triangleCount = 0;
  std::vector<std::pair<TriangleIndex, Triangle>> rewritten;  // old values, in rewrite order
  std::vector<TaggedEdge> tags;                               // old tags, when tagsChanged
  bool tagsChanged = false;
};

// What a caller already knows, so a grab need not scan every triangle (all optional). The result
// is the same bit for bit with or without them: a triangle hint is used only when q lies inside it
// farther than the snap distance from its edges, where the scan would find that same triangle.
struct InsertionHints {
  double sheetSize = 0.0;                   // sheetSize(sheet); 0: measured
  TriangleIndex triangle = kNoIndex;        // a triangle holding q (a picked surface point's)
  const VertexTriangles* around = nullptr;  // the sheet's triangles per vertex, before insertion
};

// insertVertexAt on the sheet itself (the same result bit for bit, without copying the sheet);
// `undo`, when given, records how to take it back with undoInsertion.
VertexIndex insertVertexInPlace(Sheet& sheet, const glm::dvec2& q, InsertionUndo* undo,
                                const InsertionHints& hints = {});
void undoInsertion(Sheet& sheet, const InsertionUndo& undo);

// The adjacency of `sheet` after an insertion, from the one before it: the rows of the few
// vertices the insertion touched are rebuilt, the others copied in blocks. Equal to
// buildAdjacency(sheet) (rows in the same order), which scans every triangle.
void adjacencyAfterInsertion(const SheetAdjacency& before, const Sheet& sheet,
                             const InsertionUndo& undo, SheetAdjacency& out);

}  // namespace curvefold
