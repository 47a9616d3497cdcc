#include "engine/geometry/nearest_vertex.hpp"

#include <glm/geometric.hpp>

namespace curvefold {

std::uint32_t nearestVertex(std::span<const glm::dvec3> positions, const glm::dvec3& point) {
  std::uint32_t at = 0;
  double nearest = 1e300;
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (const double d = glm::distance(positions[v], point); d < nearest) {
      nearest = d;
      at = static_cast<std::uint32_t>(v);
    }
  return at;
}

}  // namespace curvefold
