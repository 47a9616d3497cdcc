#include "engine/fit/replayed_motion.hpp"

#include <algorithm>
#include <cstdint>
#include <map>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <glm/geometric.hpp>

#include "engine/fit/eigen_glm.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/boundary_edges.hpp"
#include "engine/geometry/surface_point.hpp"

namespace curvefold {
namespace {

// Pairs spread over the target: enough to fix a motion well, few enough to be cheap.
constexpr std::size_t kPairs = 300;

std::optional<RigidMotion> rigidFit(const std::vector<glm::dvec3>& from,
                                    const std::vector<glm::dvec3>& to, double tolerance) {
  if (from.size() < 4) return std::nullopt;
  Eigen::Matrix3Xd source(3, from.size()), goal(3, to.size());
  for (std::size_t i = 0; i < from.size(); ++i) {
    source.col(Eigen::Index(i)) = eigenOf(from[i]);
    goal.col(Eigen::Index(i)) = eigenOf(to[i]);
  }
  const Eigen::Matrix4d m = Eigen::umeyama(source, goal, false);
  RigidMotion motion;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) motion.linear[c][r] = m(r, c);
    motion.offset[r] = m(r, 3);
  }
  for (std::size_t i = 0; i < from.size(); ++i)
    if (!(glm::distance(motion(from[i]), to[i]) <= tolerance)) return std::nullopt;
  return motion;
}

}  // namespace

std::optional<RigidMotion> restOntoTarget(const Sheet& initial, const Sheet& folded,
                                          const std::vector<glm::dvec3>& onSheet,
                                          const TriangleMesh& target,
                                          const std::vector<ReflectionPlane>& planes,
                                          double tolerance) {
  if (onSheet.size() != target.positions.size() || target.positions.empty() ||
      initial.triangleCount() == 0)
    return std::nullopt;
  const std::vector<char> onBoundary = boundaryVertexFlags(target);
  const double size = std::max(sheetSize(initial), 1e-9);
  const std::size_t stride = 1 + target.positions.size() / kPairs;
  // Grouped by side of each plane read (up to 64), all pairs together first.
  std::vector<glm::dvec3> from, to;
  std::map<std::uint64_t, std::pair<std::vector<glm::dvec3>, std::vector<glm::dvec3>>> groups;
  for (std::size_t v = 0; v < target.positions.size(); v += stride) {
    if (onBoundary[v]) continue;
    const glm::dvec2 at = developmentOf(initial, closestSurfacePoint(initial, onSheet[v]));
    const std::optional<SurfacePoint> there = locateDevelopmentPoint(folded, at, 1e-6 * size);
    if (!there) continue;
    from.push_back(positionOf(folded, *there));
    to.push_back(target.positions[v]);
    std::uint64_t sides = 0;
    for (std::size_t p = 0; p < planes.size() && p < 64; ++p)
      if (planes[p].signedDistance(onSheet[v]) > 0.0) sides |= std::uint64_t(1) << p;
    groups[sides].first.push_back(from.back());
    groups[sides].second.push_back(to.back());
  }
  if (const std::optional<RigidMotion> all = rigidFit(from, to, tolerance)) return all;
  std::optional<RigidMotion> best;
  std::size_t most = 0;
  for (const auto& [sides, pairs] : groups) {
    if (pairs.first.size() <= most) continue;
    if (const std::optional<RigidMotion> motion = rigidFit(pairs.first, pairs.second, tolerance)) {
      best = motion;
      most = pairs.first.size();
    }
  }
  return best;
}

std::vector<FewerPlaneRest> fewerPlaneRests(const RigidMotion& rest, const glm::dvec3& centre,
                                            const std::vector<Isometry>& images) {
  std::vector<FewerPlaneRest> found;
  // One mirror: through the plane bisecting the centre and where rest takes it.
  const glm::dvec3 moved = rest(centre);
  const double apart = glm::distance(moved, centre);
  if (apart > 1e-9 * (1.0 + glm::length(centre))) {
    const glm::dvec3 n = (moved - centre) / apart;
    const glm::dvec3 through = 0.5 * (moved + centre);
    const RigidMotion mirror = reflectionOf({through, n});
    found.push_back({mirror, then(rest, inverse(mirror))});  // s = W^-1 rest
  }
  // rest = (rest g^-1) g for each image g of the design's symmetry.
  for (const Isometry& g : images) {
    const RigidMotion s{g.linear, g.offset};
    found.push_back({then(inverse(s), rest), s});
  }
  return found;
}

RigidMotion snappedToFewPlanes(const RigidMotion& motion, double angle, double shift) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(eigenOf(motion.linear),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d A = svd.matrixU() * svd.matrixV().transpose();
  const glm::dvec3 t = motion.offset;
  if (A.determinant() < 0.0) {
    // A mirror is -1 along its normal: the eigenvector of A's symmetric part with the least
    // eigenvalue.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(0.5 * (A + A.transpose()));
    const glm::dvec3 n = glm::normalize(glmOf(Eigen::Vector3d(solver.eigenvectors().col(0))));
    const glm::dmat3 mirror = glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n);
    const glm::dvec3 across = t - glm::dot(t, n) * n;
    if ((eigenOf(mirror) - A).norm() > angle || glm::length(across) > shift) return motion;
    return {mirror, glm::dot(t, n) * n};
  }
  const Eigen::AngleAxisd turn(A);
  if (std::abs(turn.angle()) < angle) return {glm::dmat3(1.0), t};  // a shift
  const glm::dvec3 axis = glm::normalize(glmOf(turn.axis()));
  const double along = glm::dot(t, axis);
  if (std::abs(along) > shift) return motion;
  RigidMotion snapped{motion.linear, t - along * axis};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) snapped.linear[c][r] = A(r, c);
  return snapped;
}

bool isSymmetryOf(const RigidMotion& motion, const Sheet& initial, double tolerance) {
  if (initial.vertexCount() == 0) return false;
  const SurfaceDistanceQuery surface(meshOf(initial), "sheet");
  const std::size_t stride = 1 + initial.vertexCount() / kPairs;
  for (std::size_t v = 0; v < initial.vertexCount(); v += stride)
    if (!(surface.distance(motion(initial.positions[v])) <= tolerance)) return false;
  return true;
}

}  // namespace curvefold
