// Area-uniform points on a triangle mesh, for measuring how far two surfaces lie apart (issue 27):
// stratified over the cumulative area, so `count` points cover the surface evenly, and the same
// for the same seed on every machine (the generator is std::mt19937_64, read through our own
// conversion to [0, 1), which the standard fixes bit for bit).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

struct SurfaceSample {
  glm::dvec3 position{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};  // of the triangle it lies on (unit)
  std::uint32_t triangle = 0;
  glm::dvec3 barycentric{1.0 / 3.0};
};

// `count` samples (none for a mesh without area). Triangles of zero area get none.
std::vector<SurfaceSample> sampleSurface(const TriangleMesh& mesh, std::size_t count,
                                         std::uint64_t seed);

}  // namespace curvefold
