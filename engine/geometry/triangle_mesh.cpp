#include "engine/geometry/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <glm/geometric.hpp>

namespace curvefold {

glm::dvec3 faceNormal(const std::vector<glm::dvec3>& positions,
                      const std::array<std::uint32_t, 3>& t) {
  const glm::dvec3 n =
      glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : glm::dvec3(0.0);
}

EdgeFaces edgeFaces(const TriangleMesh& mesh) {
  EdgeFaces faces;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = mesh.triangles[t][i], v = mesh.triangles[t][(i + 1) % 3];
      faces[{std::min(u, v), std::max(u, v)}].push_back(t);
    }
  return faces;
}

TriangleMesh meshOf(const Sheet& sheet) {
  TriangleMesh mesh;
  mesh.positions = sheet.positions;
  mesh.triangles.reserve(sheet.triangleCount());
  for (const Triangle& t : sheet.triangles) mesh.triangles.push_back({t[0], t[1], t[2]});
  return mesh;
}

double surfaceArea(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]],
                     &c = mesh.positions[t[2]];
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  return area;
}

double boundingDiagonal(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return 0.0;
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-low);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) {
      low = glm::min(low, mesh.positions[v]);
      high = glm::max(high, mesh.positions[v]);
    }
  return glm::length(high - low);
}

std::optional<std::string> unmeasurableVertex(const TriangleMesh& mesh) {
  for (const auto& triangle : mesh.triangles)
    for (const std::uint32_t v : triangle) {
      const glm::dvec3& p = mesh.positions[v];
      // Written so that NaN fails it too.
      if (std::abs(p.x) <= kMaxMeasurableCoordinate && std::abs(p.y) <= kMaxMeasurableCoordinate &&
          std::abs(p.z) <= kMaxMeasurableCoordinate)
        continue;
      std::ostringstream text;
      text.precision(6);
      text << "vertex " << std::size_t(v) + 1 << " lies at (" << p.x << ", " << p.y << ", " << p.z
           << ")";
      if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
        text << ", beyond " << kMaxMeasurableCoordinate
             << " m of the origin: too far out to measure";
      else
        text << ": not a point (coordinates must be finite numbers)";
      return text.str();
    }
  return std::nullopt;
}

}  // namespace curvefold
