// Vertex normals of a sheet: each vertex's incident triangles' normals weighted by their areas
// (the sum of the unnormalized cross products), normalized.
//
// Input: a sheet (positions and triangles). Output: one unit normal per vertex, oriented with the
// triangles' winding (b - a) x (c - a); the zero vector for a vertex with no triangle or whose
// triangles' normals cancel.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

std::vector<glm::dvec3> vertexNormals(const Sheet& sheet);

}  // namespace curvefold
