#include "engine/fit/surface_samples.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "engine/fit/unit_draw.hpp"

namespace curvefold {

std::vector<SurfaceSample> sampleSurface(const TriangleMesh& mesh, std::size_t count,
                                         std::uint64_t seed) {
  std::vector<double> cumulative(mesh.triangles.size());
  double total = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const glm::dvec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]],
                     &c = mesh.positions[tri[2]];
    total += 0.5 * glm::length(glm::cross(b - a, c - a));
    cumulative[t] = total;
  }
  std::vector<SurfaceSample> samples;
  if (!(total > 0.0) || count == 0) return samples;
  samples.reserve(count);
  std::mt19937_64 random(seed);
  for (std::size_t i = 0; i < count; ++i) {
    // One point per equal slice of the cumulative area (stratified): every part of the surface
    // gets its share of points, though two may still fall close together across a slice's edge.
    const double at = (static_cast<double>(i) + unit(random)) / static_cast<double>(count) * total;
    const std::size_t t = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin(),
        cumulative.size() - 1);
    const auto& tri = mesh.triangles[t];
    const glm::dvec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]],
                     &c = mesh.positions[tri[2]];
    // Uniform in the triangle: the square-root warp of two uniform numbers.
    const double r1 = std::sqrt(unit(random)), r2 = unit(random);
    SurfaceSample sample;
    sample.triangle = static_cast<std::uint32_t>(t);
    sample.barycentric = {1.0 - r1, r1 * (1.0 - r2), r1 * r2};
    sample.position =
        sample.barycentric.x * a + sample.barycentric.y * b + sample.barycentric.z * c;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (length > 0.0) sample.normal = n / length;
    samples.push_back(sample);
  }
  return samples;
}

}  // namespace curvefold
