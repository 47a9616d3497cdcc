#pragma once
// Conversions between GLM (the mesh's types) and Eigen (the fit's solvers). GLM matrices are
// column-major, indexed [column][row]; Eigen's are indexed (row, column).

#include <Eigen/Core>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace curvefold {

inline Eigen::Vector3d eigenOf(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}

inline glm::dvec3 glmOf(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

inline Eigen::Matrix3d eigenOf(const glm::dmat3& m) {
  Eigen::Matrix3d e;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) e(r, c) = m[c][r];
  return e;
}

inline glm::dmat3 glmOf(const Eigen::Matrix3d& e) {
  glm::dmat3 m;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] = e(r, c);
  return m;
}

}  // namespace curvefold
