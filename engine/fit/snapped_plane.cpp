#include "engine/fit/snapped_plane.hpp"

#include <cmath>

#include <Eigen/Dense>
#include <glm/geometric.hpp>

namespace curvefold {

std::optional<ReflectionPlane> planeThroughNearPoints(const ReflectionPlane& plane,
                                                      const std::vector<glm::dvec3>& points,
                                                      double reach, double size, double onPlane) {
  std::vector<glm::dvec3> near;
  for (const glm::dvec3& p : points)
    if (std::abs(plane.signedDistance(p)) <= reach) near.push_back(p);
  if (near.empty()) return std::nullopt;
  // The plane n . (x - c) = e, from n, e = 0: each near point's row asks dn . (p - c) - de = -r,
  // solved for the least |dn|^2 + (de / size)^2 (the minimum-norm solution: a row of collinear
  // points leaves the turn about their line free, and it stays as read).
  const glm::dvec3 c = plane.point;
  Eigen::MatrixXd a(near.size(), 4);
  Eigen::VectorXd b(near.size());
  for (std::size_t i = 0; i < near.size(); ++i) {
    const glm::dvec3 q = near[i] - c;
    a.row(static_cast<Eigen::Index>(i)) << q.x, q.y, q.z, -size;
    b(static_cast<Eigen::Index>(i)) = -glm::dot(plane.normal, q);
  }
  const Eigen::Vector4d x = a.completeOrthogonalDecomposition().solve(b);
  const glm::dvec3 turned = plane.normal + glm::dvec3(x(0), x(1), x(2));
  const double length = glm::length(turned);
  if (!(length > 0.5)) return std::nullopt;
  const glm::dvec3 normal = turned / length;
  const ReflectionPlane snapped{c + (size * x(3) / length) * normal, normal};
  for (const glm::dvec3& p : near)
    if (!(std::abs(snapped.signedDistance(p)) <= onPlane)) return std::nullopt;
  return snapped;
}

}  // namespace curvefold
