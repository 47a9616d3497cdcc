#include "engine/simulation/rigid_placement.hpp"

#include <Eigen/Dense>

namespace curvefold {

RigidPlacement bestRigidPlacement(const std::vector<glm::dvec3>& from,
                                  const std::vector<glm::dvec3>& to) {
  RigidPlacement placement;
  const std::size_t n = from.size();
  if (n < 3 || to.size() != n) return placement;
  glm::dvec3 fromCentre(0.0), toCentre(0.0);
  for (std::size_t i = 0; i < n; ++i) {
    fromCentre += from[i];
    toCentre += to[i];
  }
  fromCentre /= static_cast<double>(n);
  toCentre /= static_cast<double>(n);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 p = from[i] - fromCentre, q = to[i] - toCentre;
    covariance += Eigen::Vector3d(q.x, q.y, q.z) * Eigen::Vector3d(p.x, p.y, p.z).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d correction = Eigen::Matrix3d::Identity();
  // A reflection fits a mirrored sheet better, but no rigid motion makes it.
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0) correction(2, 2) = -1.0;
  const Eigen::Matrix3d rotation = svd.matrixU() * correction * svd.matrixV().transpose();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) placement.rotation[c][r] = rotation(r, c);
  placement.translation = toCentre - placement.rotation * fromCentre;
  return placement;
}

std::vector<glm::dvec3> placed(const RigidPlacement& placement,
                               const std::vector<glm::dvec3>& points) {
  std::vector<glm::dvec3> result;
  result.reserve(points.size());
  for (const glm::dvec3& p : points) result.push_back(placement.apply(p));
  return result;
}

}  // namespace curvefold
