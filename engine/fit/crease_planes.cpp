#include "engine/fit/crease_planes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "engine/fit/unit_draw.hpp"

namespace curvefold {
namespace {

struct SharpEdge {
  glm::dvec3 a{0.0}, b{0.0};
  glm::dvec3 na{0.0}, nb{0.0};  // the two faces' unit normals
  double length = 0.0;
};

// Each edge with exactly two faces, with the angle its faces turn by (degrees).
template <typename Visit>
void forEachInteriorEdge(const TriangleMesh& mesh, Visit visit) {
  for (const auto& [edge, around] : edgeFaces(mesh)) {
    if (around.size() != 2) continue;
    const glm::dvec3 n1 = faceNormal(mesh.positions, mesh.triangles[around[0]]);
    const glm::dvec3 n2 = faceNormal(mesh.positions, mesh.triangles[around[1]]);
    if (n1 == glm::dvec3(0.0) || n2 == glm::dvec3(0.0)) continue;
    // Two faces that share an edge the same way up have the same normal when flat.
    const double degrees =
        std::acos(std::clamp(glm::dot(n1, n2), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    visit(edge.first, edge.second, n1, n2, degrees);
  }
}

constexpr double kMinimumSharpDegrees = 4.0;
// A crease this long (of the diagonal) names a plane: a fold of a corner makes a short one.
constexpr double kMinimumSupport = 0.005;

}  // namespace

double largestDihedralDegrees(const TriangleMesh& mesh) {
  double largest = 0.0;
  forEachInteriorEdge(mesh, [&](auto, auto, const auto&, const auto&, double degrees) {
    largest = std::max(largest, degrees);
  });
  return largest;
}

double sharpEdgeThreshold(const TriangleMesh& initialSheet) {
  // A flat sheet's faces do not bend at all: a shallow fold (a drag mostly off the sheet bends
  // it by a few degrees) is read there as well as a steep one.
  return std::max(kMinimumSharpDegrees, 1.5 * largestDihedralDegrees(initialSheet) + 2.0);
}

std::vector<CreasePlane> findCreasePlanes(const TriangleMesh& mesh,
                                          const CreasePlaneOptions& options) {
  const double diagonal = boundingDiagonal(mesh);
  const double tolerance = options.tolerance > 0.0 ? options.tolerance : 1e-4 * diagonal;
  const double minSupport =
      options.minSupport > 0.0 ? options.minSupport : kMinimumSupport * diagonal;
  std::vector<SharpEdge> sharp;
  forEachInteriorEdge(mesh, [&](std::uint32_t u, std::uint32_t v, const glm::dvec3& n1,
                                const glm::dvec3& n2, double degrees) {
    if (degrees < options.minDihedralDegrees) return;
    SharpEdge e{mesh.positions[u], mesh.positions[v], n1, n2, 0.0};
    e.length = glm::distance(e.a, e.b);
    if (e.length > 0.0) sharp.push_back(e);
  });

  std::vector<CreasePlane> planes;
  std::vector<char> used(sharp.size(), 0);
  std::mt19937_64 random(options.seed);
  // An edge is in a fold's plane when it lies in it and the plane mirrors one face's
  // normal onto the other's (up to sign): the plane of a flat region that holds two creases
  // lies along both, but mirrors neither. Within the threshold, not less: where a crease runs
  // along an edge of a curved sheet's facets, its faces come from two facets, which bent apart
  // by up to two thirds of it before the fold.
  const double consistent = std::cos(options.minDihedralDegrees * std::numbers::pi / 180.0);
  auto holds = [&](const ReflectionPlane& plane, const SharpEdge& e) {
    if (std::abs(plane.signedDistance(e.a)) > tolerance ||
        std::abs(plane.signedDistance(e.b)) > tolerance)
      return false;
    const glm::dvec3 mirrored = e.na - 2.0 * glm::dot(e.na, plane.normal) * plane.normal;
    return std::abs(glm::dot(mirrored, e.nb)) >= consistent;
  };
  auto support = [&](const ReflectionPlane& plane) {
    double total = 0.0;
    for (std::size_t i = 0; i < sharp.size(); ++i)
      if (!used[i] && holds(plane, sharp[i])) total += sharp[i].length;
    return total;
  };
  while (planes.size() < options.maxPlanes) {
    std::vector<std::size_t> open;
    for (std::size_t i = 0; i < sharp.size(); ++i)
      if (!used[i]) open.push_back(i);
    if (open.empty()) break;
    CreasePlane best;
    auto consider = [&](const glm::dvec3& point, glm::dvec3 normal) {
      const double length = glm::length(normal);
      if (!(length > 1e-9)) return;
      const ReflectionPlane plane{point, normal / length};
      const double s = support(plane);
      if (s > best.support) best = {plane, s};
    };
    // Straight creases: the bisectors of each sharp edge's faces, through it (of at most 400
    // edges, spread over all).
    const std::size_t stride = std::max<std::size_t>(1, open.size() / 400);
    for (std::size_t k = 0; k < open.size(); k += stride) {
      const SharpEdge& e = sharp[open[k]];
      const glm::dvec3 middle = 0.5 * (e.a + e.b), along = (e.b - e.a) / e.length;
      for (const glm::dvec3 n : {e.na + e.nb, e.na - e.nb})
        consider(middle, n - glm::dot(n, along) * along);
    }
    // Curved creases: three points of sharp edges.
    for (std::size_t k = 0; k < options.hypotheses; ++k) {
      const SharpEdge& e = sharp[open[std::size_t(unit(random) * open.size()) % open.size()]];
      const SharpEdge& f = sharp[open[std::size_t(unit(random) * open.size()) % open.size()]];
      const glm::dvec3 n = glm::cross(e.b - e.a, f.a - e.a);
      // Nearly collinear points leave the plane free to turn: only a wide triangle counts.
      if (glm::length(n) < 1e-2 * e.length * glm::distance(f.a, e.a)) continue;
      consider(e.a, n);
    }
    if (best.support < minSupport) break;
    for (std::size_t i : open)
      if (holds(best.plane, sharp[i])) used[i] = 1;
    planes.push_back(best);
  }
  return planes;
}

}  // namespace curvefold
