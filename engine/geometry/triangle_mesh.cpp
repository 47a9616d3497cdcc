#include "engine/geometry/triangle_mesh.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include <glm/geometric.hpp>

namespace curvefold {

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
