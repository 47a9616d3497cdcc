// Where two surfaces lie farthest apart (issue 38, 2d): the point of each farthest from the
// other, among area-uniform samples (surface_samples.hpp), measured exactly to the other surface
// (surface_distance.hpp). What a fit's distance line does not say: where to look.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

struct FarthestPoints {
  glm::dvec3 onA{0.0}, onB{0.0};  // A's sample farthest from B, and B's from A
  double fromA = 0.0, fromB = 0.0;
};

// Throws DegenerateMesh for a mesh without area.
FarthestPoints farthestPoints(const TriangleMesh& a, const TriangleMesh& b,
                              std::size_t samples = 20'000, std::uint64_t seed = 1);
// The same against B's tree made once (a fit's target).
FarthestPoints farthestPoints(const TriangleMesh& a, const MeasuredSurface& b,
                              std::size_t samples = 20'000, std::uint64_t seed = 1);

}  // namespace curvefold
