#include "engine/fit/farthest_points.hpp"

#include <vector>

#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"

namespace curvefold {
namespace {

// The sample of `from` farthest from `to`.
void farthestOf(const TriangleMesh& from, const SurfaceDistanceQuery& to, std::size_t samples,
                std::uint64_t seed, glm::dvec3& at, double& distance) {
  for (const SurfaceSample& s : sampleSurface(from, samples, seed)) {
    const double d = to.distance(s.position);
    if (d > distance) {
      distance = d;
      at = s.position;
    }
  }
}

}  // namespace

FarthestPoints farthestPoints(const TriangleMesh& a, const TriangleMesh& b, std::size_t samples,
                              std::uint64_t seed) {
  const SurfaceDistanceQuery toA(a, "first"), toB(b, "second");
  FarthestPoints result;
  farthestOf(a, toB, samples, seed, result.onA, result.fromA);
  farthestOf(b, toA, samples, seed + 1, result.onB, result.fromB);
  return result;
}

FarthestPoints farthestPoints(const TriangleMesh& a, const MeasuredSurface& b, std::size_t samples,
                              std::uint64_t seed) {
  const SurfaceDistanceQuery toA(a, "first");
  FarthestPoints result;
  farthestOf(a, b.query(), samples, seed, result.onA, result.fromA);
  farthestOf(b.mesh(), toA, samples, seed + 1, result.onB, result.fromB);
  return result;
}

}  // namespace curvefold
