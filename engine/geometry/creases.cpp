#include "engine/geometry/creases.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

namespace curvefold {
namespace {

glm::dvec3 frontNormal(const Sheet& sheet, TriangleIndex t) {
  const Triangle& tri = sheet.triangles[t];
  const glm::dvec3& a = sheet.positions[tri[0]];
  return glm::normalize(glm::cross(sheet.positions[tri[1]] - a, sheet.positions[tri[2]] - a));
}

double distanceToLine(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 direction = b - a;
  const double lengthSquared = glm::dot(direction, direction);
  if (lengthSquared == 0.0) return glm::distance(p, a);
  const double t = glm::dot(p - a, direction) / lengthSquared;
  return glm::distance(p, a + t * direction);
}

}  // namespace

double planarityError(std::span<const glm::dvec3> points) {
  if (points.empty()) return 0.0;
  // Plane through three well-spread points: p0, p1 farthest from it, p2 farthest from their line.
  const glm::dvec3 p0 = points.front();
  glm::dvec3 p1 = p0;
  for (const glm::dvec3& p : points)
    if (glm::distance(p, p0) > glm::distance(p1, p0)) p1 = p;
  glm::dvec3 p2 = p0;
  double lineError = 0.0;  // the largest distance from the line p0 p1
  for (const glm::dvec3& p : points) {
    const double d = distanceToLine(p, p0, p1);
    if (d > lineError) {
      lineError = d;
      p2 = p;
    }
  }
  // Every plane through the line is within lineError of the points: a straight chain is planar.
  const glm::dvec3 along = p1 - p0;
  if (lineError == 0.0 || glm::dot(along, along) == 0.0) return lineError;
  // The normal from along and the part of p2 - p0 across it (Gram-Schmidt), not from p2 - p0
  // itself: for a nearly straight chain the cross product with p2 - p0 is mostly rounding, and
  // its tilt put rounding-sized chains 1e-9 m off their own plane.
  glm::dvec3 across = p2 - p0;
  across -= along * (glm::dot(across, along) / glm::dot(along, along));
  const glm::dvec3 normal = glm::cross(along, across);
  if (glm::dot(normal, normal) == 0.0) return lineError;
  const glm::dvec3 unit = glm::normalize(normal);
  double planeError = 0.0;
  for (const glm::dvec3& p : points)
    planeError = std::max(planeError, std::abs(glm::dot(p - p0, unit)));
  // Both bound the distance to the best plane from above; the smaller is the tighter.
  return std::min(lineError, planeError);
}

double foldAngleDegrees(const Sheet& sheet, const EdgeTopology::EdgeSides& sides) {
  if (sides.left == kNoIndex || sides.right == kNoIndex) return 0.0;
  // left runs a->b; turning from its normal to right's about that direction is negative for a
  // valley, where right's far side rises toward left's front.
  const glm::dvec3 n1 = frontNormal(sheet, sides.left);
  const glm::dvec3 n2 = frontNormal(sheet, sides.right);
  const glm::dvec3 along =
      glm::normalize(sheet.positions[sides.edge.b] - sheet.positions[sides.edge.a]);
  const double radians = std::atan2(-glm::dot(glm::cross(n1, n2), along), glm::dot(n1, n2));
  return radians * 180.0 / std::numbers::pi;
}

Assignment assignmentOf(const Sheet& sheet, const EdgeTopology::EdgeSides& sides,
                        double foldAngle) {
  const std::optional<EdgeKind> kind = sheet.edgeKind(sides.edge);
  if (sides.isBoundary()) return kind == EdgeKind::Slit ? Assignment::Cut : Assignment::Boundary;
  if (kind != EdgeKind::Crease || std::abs(foldAngle) < kFlatCreaseDegrees) return Assignment::Flat;
  return foldAngle > 0.0 ? Assignment::Valley : Assignment::Mountain;
}

std::vector<CreaseEdge> creaseEdges(const Sheet& sheet, const EdgeTopology& edges) {
  std::vector<CreaseEdge> result;
  for (const TaggedEdge& tag : sheet.tags) {
    if (tag.kind != EdgeKind::Crease) continue;
    const std::uint32_t e = edges.find(tag.edge);
    if (e == kNoIndex) continue;
    const double angle = foldAngleDegrees(sheet, edges.edges[e]);
    result.push_back({tag.edge, angle, assignmentOf(sheet, edges.edges[e], angle)});
  }
  return result;
}

std::vector<CreaseCurve> creaseCurves(const Sheet& sheet, const EdgeTopology& edges) {
  const std::vector<CreaseEdge> creases = creaseEdges(sheet, edges);
  // Crease graph as adjacency lists.
  std::vector<std::vector<std::uint32_t>> incident(sheet.vertexCount());
  for (std::uint32_t i = 0; i < creases.size(); ++i) {
    incident[creases[i].edge.a].push_back(i);
    incident[creases[i].edge.b].push_back(i);
  }
  std::vector<bool> used(creases.size(), false);
  auto other = [&](std::uint32_t e, VertexIndex v) {
    return creases[e].edge.a == v ? creases[e].edge.b : creases[e].edge.a;
  };
  auto walk = [&](VertexIndex start, std::uint32_t firstEdge) {
    CreaseCurve curve;
    curve.vertices.push_back(start);
    std::uint32_t e = firstEdge;
    VertexIndex v = start;
    while (true) {
      used[e] = true;
      v = other(e, v);
      curve.vertices.push_back(v);
      if (incident[v].size() != 2 || v == start) break;
      const std::uint32_t next = incident[v][0] == e ? incident[v][1] : incident[v][0];
      if (used[next]) break;
      e = next;
    }
    curve.closed = curve.vertices.front() == curve.vertices.back();
    std::vector<glm::dvec3> points;
    points.reserve(curve.vertices.size());
    for (VertexIndex v : curve.vertices) points.push_back(sheet.positions[v]);
    curve.planarityError = planarityError(points);
    return curve;
  };
  std::vector<CreaseCurve> curves;
  // Open chains start at junctions and ends; what remains are closed loops.
  for (VertexIndex v = 0; v < incident.size(); ++v)
    if (incident[v].size() != 2)
      for (std::uint32_t e : incident[v])
        if (!used[e]) curves.push_back(walk(v, e));
  for (std::uint32_t e = 0; e < creases.size(); ++e)
    if (!used[e]) curves.push_back(walk(creases[e].edge.a, e));
  return curves;
}

}  // namespace curvefold
