#include "engine/fit/surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/cgal/triangle_tree.hpp"
#include "engine/fit/surface_samples.hpp"

namespace curvefold {

// The closest-point queries of one mesh: its triangles with area (CGAL's queries assume them).
struct SurfaceDistanceQuery::Tree {
  Tree(const TriangleMesh& mesh, const char* which) {
    // A vertex at 1e300 would give "inf mm" and a NaN ratio, not a distance.
    if (const std::optional<std::string> why = unmeasurableVertex(mesh))
      throw DegenerateMesh(std::string("the ") + which + " surface's " + *why);
    for (const auto& t : mesh.triangles) {
      CgalTriangle triangle(cgalPoint(mesh.positions[t[0]]), cgalPoint(mesh.positions[t[1]]),
                            cgalPoint(mesh.positions[t[2]]));
      if (!triangle.is_degenerate()) tree_.triangles.push_back(triangle);
    }
    if (tree_.triangles.empty())
      throw DegenerateMesh(std::string("the ") + which + " surface has no triangle with area");
    tree_.build();
    // The search structure is made by the first query: make it here, before queries run in
    // parallel.
    distance(mesh.positions[mesh.triangles.front()[0]]);
  }
  double distance(const glm::dvec3& p) const {
    return std::sqrt(tree_.tree.squared_distance(cgalPoint(p)));
  }

  glm::dvec3 closest(const glm::dvec3& p) const {
    const auto q = tree_.tree.closest_point(cgalPoint(p));
    return {CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
  }

  CgalTriangleTree tree_;
};

SurfaceDistanceQuery::SurfaceDistanceQuery(const TriangleMesh& mesh, const char* which)
    : tree_(std::make_unique<Tree>(mesh, which)) {}
SurfaceDistanceQuery::~SurfaceDistanceQuery() = default;
double SurfaceDistanceQuery::distance(const glm::dvec3& p) const {
  return tree_->distance(p);
}
glm::dvec3 SurfaceDistanceQuery::closestPoint(const glm::dvec3& p) const {
  return tree_->closest(p);
}

std::vector<double> pointDistances(std::span<const glm::dvec3> points,
                                   const SurfaceDistanceQuery& to) {
  std::vector<double> distances(points.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) distances[i] = to.distance(points[i]);
  });
  return distances;
}

namespace {

struct OneSide {
  double max = 0.0, mean = 0.0;
};

// Samples of `from` (and its used vertices, for the maximum) measured to `to`.
OneSide measureSide(const TriangleMesh& from, const SurfaceDistanceQuery& to, std::size_t count,
                    std::uint64_t seed) {
  const std::vector<SurfaceSample> samples = sampleSurface(from, count, seed);
  std::vector<char> used(from.positions.size(), 0);
  for (const auto& t : from.triangles)
    for (std::uint32_t v : t) used[v] = 1;
  std::vector<glm::dvec3> vertices;
  for (std::size_t v = 0; v < from.positions.size(); ++v)
    if (used[v]) vertices.push_back(from.positions[v]);
  std::vector<double> sampleDistance(samples.size()), vertexDistance(vertices.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      sampleDistance[i] = to.distance(samples[i].position);
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size(), 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) vertexDistance[i] = to.distance(vertices[i]);
  });
  OneSide side;
  double sum = 0.0;
  for (double d : sampleDistance) {
    sum += d;
    side.max = std::max(side.max, d);
  }
  for (double d : vertexDistance) side.max = std::max(side.max, d);
  side.mean = samples.empty() ? 0.0 : sum / static_cast<double>(samples.size());
  return side;
}

}  // namespace

SurfaceDistance surfaceDistance(const TriangleMesh& a, const TriangleMesh& b, std::size_t samples,
                                std::uint64_t seed) {
  const SurfaceDistanceQuery toA(a, "first"), toB(b, "second");
  const OneSide fromA = measureSide(a, toB, samples, seed);
  const OneSide fromB = measureSide(b, toA, samples, seed + 1);
  SurfaceDistance result;
  result.fromAMax = fromA.max;
  result.fromAMean = fromA.mean;
  result.fromBMax = fromB.max;
  result.fromBMean = fromB.mean;
  result.hausdorff = std::max(fromA.max, fromB.max);
  result.chamfer = 0.5 * (fromA.mean + fromB.mean);
  result.diagonal = boundingDiagonal(b);
  return result;
}

}  // namespace curvefold
