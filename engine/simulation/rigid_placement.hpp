// The best rigid placement of one point set onto another with the same numbering (least squares;
// Kabsch, "A solution for the best rotation to relate two sets of vectors", Acta Cryst. A32,
// 1976, by SVD with the reflection case excluded), so a free-floating simulated sheet can be
// compared with, or shown in the frame of, the design it folds toward.
#pragma once

#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace curvefold {

struct RigidPlacement {
  glm::dmat3 rotation{1.0};
  glm::dvec3 translation{0.0};
  glm::dvec3 apply(const glm::dvec3& p) const { return rotation * p + translation; }
};

// The rotation and translation taking `from` closest to `to` (same length; the identity for
// fewer than three points).
RigidPlacement bestRigidPlacement(const std::vector<glm::dvec3>& from,
                                  const std::vector<glm::dvec3>& to);

// `points` moved by the placement.
std::vector<glm::dvec3> placed(const RigidPlacement& placement,
                               const std::vector<glm::dvec3>& points);

}  // namespace curvefold
