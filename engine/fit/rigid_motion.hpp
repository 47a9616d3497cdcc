// A rigid motion x -> linear x + offset (linear orthogonal: a rotation, or a rotation times a
// mirror), the reflections that make one, and their composition. Shared by registration
// (whole_sheet_folds.hpp), the unfolding (target_unfolding.hpp), the replayed folds
// (replayed_motion.hpp) and the fit (fold_fit.hpp).
#pragma once

#include <glm/geometric.hpp>
#include <glm/gtx/matrix_operation.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/reflection.hpp"

namespace curvefold {

// x -> linear x + offset, linear orthogonal.
struct RigidMotion {
  glm::dmat3 linear{1.0};
  glm::dvec3 offset{0.0};
  glm::dvec3 operator()(const glm::dvec3& x) const { return linear * x + offset; }
};

// x -> H x + 2 (n.p) n, the reflection through the plane (H = I - 2 n n^T).
inline RigidMotion reflectionOf(const ReflectionPlane& plane) {
  const glm::dvec3 n = plane.normal;
  return {glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n), 2.0 * glm::dot(n, plane.point) * n};
}

// x -> second(first(x)).
inline RigidMotion then(const RigidMotion& first, const RigidMotion& second) {
  return {second.linear * first.linear, second.linear * first.offset + second.offset};
}

// The motion back (linear orthogonal: its transpose is its inverse).
inline RigidMotion inverse(const RigidMotion& m) {
  const glm::dmat3 back = glm::transpose(m.linear);
  return {back, -(back * m.offset)};
}

}  // namespace curvefold
