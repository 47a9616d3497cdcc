// A plain triangle mesh: a shape a sheet is compared with (a fit's target, either side of a
// distance). Unlike a Sheet it has no development and need not be manifold, oriented or
// developable: a scan or a sculpted surface is one.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Triangle t's unit normal (right-handed from its corner order), or zero for a degenerate one.
glm::dvec3 faceNormal(const std::vector<glm::dvec3>& positions,
                      const std::array<std::uint32_t, 3>& t);

// Each edge (lower vertex first, in that order) with the triangles that have it, in index order:
// one for a boundary edge, two inside a manifold, more where a mesh is not one.
using EdgeFaces = std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>>;
EdgeFaces edgeFaces(const TriangleMesh& mesh);

// The sheet's folded form as a plain mesh.
TriangleMesh meshOf(const Sheet& sheet);

// Sum of the triangles' areas, m^2.
double surfaceArea(const TriangleMesh& mesh);

// Diagonal of the bounding box of the vertices that triangles use (0 when there are none).
double boundingDiagonal(const TriangleMesh& mesh);

// How far from the origin a shape to measure may reach, in metres (a million kilometres): beyond
// it areas, diagonals and squared distances lose every digit or overflow (1e300 squared is
// infinite), and a distance would print as "inf mm" or a ratio as NaN.
inline constexpr double kMaxMeasurableCoordinate = 1e9;

// The first vertex a triangle uses whose coordinates are not finite or reach beyond
// kMaxMeasurableCoordinate, said in one line: "vertex 3 lies at (1e+300, 0, 0), beyond 1e+09 m
// of the origin: too far out to measure" (vertices counted from 1, as OBJ does); or nothing.
std::optional<std::string> unmeasurableVertex(const TriangleMesh& mesh);

}  // namespace curvefold
