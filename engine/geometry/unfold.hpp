// Development of a triangle mesh given only in 3D: triangles are laid flat one by one across
// shared edges, then every triangle is checked against its 3D shape. A mesh that is not
// developable is refused with its largest angle defect.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct AngleDefect {
  VertexIndex vertex = kNoIndex;
  double radians = 0.0;  // 2*pi minus the sum of the angles around an interior vertex
};

// Each vertex's angle defect (2*pi minus the sum of its corner angles), NaN for a vertex on the
// boundary or in no triangle.
std::vector<double> angleDefects(const std::vector<glm::dvec3>& positions,
                                 const std::vector<Triangle>& triangles);

// Largest |angle defect| over interior vertices (vertex kNoIndex when there are none).
AngleDefect largestAngleDefect(const std::vector<glm::dvec3>& positions,
                               const std::vector<Triangle>& triangles);

// Thrown when a mesh cannot be unfolded; the message names the largest angle defect or the edge
// whose development disagrees with its 3D length.
class NotDevelopable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Computes the development of a mesh (positions and triangles given, consistently oriented), so
// that each triangle is counter-clockwise. relativeTolerance is relative to the mesh's size.
std::vector<glm::dvec2> unfoldDevelopment(const std::vector<glm::dvec3>& positions,
                                          const std::vector<Triangle>& triangles,
                                          double relativeTolerance = kRelativeIsometryTolerance);

}  // namespace curvefold
