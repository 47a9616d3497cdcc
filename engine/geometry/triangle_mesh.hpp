// A plain triangle mesh: a shape a sheet is compared with (a fit's target, either side of a
// distance). Unlike a Sheet it has no development and need not be manifold, oriented or
// developable: a scan or a sculpted surface is one.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// The sheet's folded form as a plain mesh.
TriangleMesh meshOf(const Sheet& sheet);

// Sum of the triangles' areas, m^2.
double surfaceArea(const TriangleMesh& mesh);

// Diagonal of the bounding box of the vertices that triangles use (0 when there are none).
double boundingDiagonal(const TriangleMesh& mesh);

}  // namespace curvefold
