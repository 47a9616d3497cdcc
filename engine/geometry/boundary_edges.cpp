#include "engine/geometry/boundary_edges.hpp"

#include <algorithm>
#include <map>

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

std::vector<std::uint32_t> boundaryVerticesAlong(const TriangleMesh& mesh) {
  std::map<std::uint32_t, std::vector<std::uint32_t>> next;  // sorted: loops start lowest
  for (const auto& [a, b] : boundaryEdges(mesh)) {
    next[a].push_back(b);
    next[b].push_back(a);
  }
  for (auto& entry : next) std::sort(entry.second.begin(), entry.second.end());
  std::vector<std::uint32_t> order;
  std::vector<char> seen(mesh.positions.size(), 0);
  for (const auto& entry : next) {
    std::uint32_t at = entry.first;
    while (!seen[at]) {
      seen[at] = 1;
      order.push_back(at);
      for (const std::uint32_t n : next.at(at))
        if (!seen[n]) {
          at = n;
          break;
        }
    }
  }
  return order;
}

}  // namespace curvefold
