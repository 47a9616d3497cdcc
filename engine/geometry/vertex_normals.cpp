#include "engine/geometry/vertex_normals.hpp"

#include <glm/geometric.hpp>

namespace curvefold {

std::vector<glm::dvec3> vertexNormals(const Sheet& sheet) {
  std::vector<glm::dvec3> normals(sheet.vertexCount(), glm::dvec3(0.0));
  for (const Triangle& t : sheet.triangles) {
    const glm::dvec3 n = glm::cross(sheet.positions[t[1]] - sheet.positions[t[0]],
                                    sheet.positions[t[2]] - sheet.positions[t[0]]);
    for (const VertexIndex v : t) normals[v] += n;  // area-weighted
  }
  for (glm::dvec3& n : normals) {
    const double length = glm::length(n);
    n = length > 0.0 ? n / length : glm::dvec3(0.0);
  }
  return normals;
}

}  // namespace curvefold
