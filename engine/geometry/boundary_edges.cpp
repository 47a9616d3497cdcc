#include "engine/geometry/boundary_edges.hpp"

namespace curvefold {

std::vector<std::pair<std::uint32_t, std::uint32_t>> boundaryEdges(const TriangleMesh& mesh) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& [edge, faces] : edgeFaces(mesh))
    if (faces.size() == 1) edges.push_back(edge);
  return edges;
}

std::vector<char> boundaryVertexFlags(const TriangleMesh& mesh) {
  std::vector<char> flags(mesh.positions.size(), 0);
  for (const auto& [a, b] : boundaryEdges(mesh)) flags[a] = flags[b] = 1;
  return flags;
}

}  // namespace curvefold
