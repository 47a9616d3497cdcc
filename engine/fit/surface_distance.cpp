#include "engine/fit/surface_distance.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>
#include <nanoflann.hpp>

#include "engine/cgal/triangle_tree.hpp"
#include "engine/fit/surface_samples.hpp"

namespace curvefold {

namespace {

std::atomic<std::uint64_t> indexedTriangles{0};

// A point cloud for nanoflann's KD-tree.
struct PointList {
  const std::vector<glm::dvec3>& points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t axis) const { return points[i][int(axis)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using PointTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointList>, PointList,
                                        3, std::uint32_t>;

}  // namespace

std::uint64_t distanceTreeTriangles() {
  return indexedTriangles.load();
}

// The closest-point queries of one mesh: its triangles with area (CGAL's queries assume them).
// A query starts from a hint, the nearest of the triangles' first vertices, as CGAL's own search
// tree gives it (its traversal then depends on that point alone: the same distances), but found
// in a nanoflann tree of the distinct vertices without allocating: CGAL's search allocated per
// query, and a fit measures hundreds of thousands (6x slower under ASan than plain, issue 38).
struct SurfaceDistanceQuery::Tree {
  Tree(const TriangleMesh& mesh, const char* which) {
    // A vertex at 1e300 would give "inf mm" and a NaN ratio, not a distance.
    if (const std::optional<std::string> why = unmeasurableVertex(mesh))
      throw DegenerateMesh(std::string("the ") + which + " surface's " + *why);
    tree_.triangles.reserve(mesh.triangles.size());
    std::vector<char> hinted(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles) {
      CgalTriangle triangle(cgalPoint(mesh.positions[t[0]]), cgalPoint(mesh.positions[t[1]]),
                            cgalPoint(mesh.positions[t[2]]));
      if (triangle.is_degenerate()) continue;
      tree_.triangles.push_back(triangle);
      if (!hinted[t[0]]) {
        hinted[t[0]] = 1;
        hints_.push_back(mesh.positions[t[0]]);
      }
    }
    if (tree_.triangles.empty())
      throw DegenerateMesh(std::string("the ") + which + " surface has no triangle with area");
    tree_.build(false);
    indexedTriangles += tree_.triangles.size();
    hintTree_ =
        std::make_unique<PointTree>(3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  }
  CgalKernel::Point_3 hint(const glm::dvec3& p) const {
    const double query[3] = {p.x, p.y, p.z};
    std::uint32_t index = 0;
    double squared = 0.0;
    hintTree_->knnSearch(query, 1, &index, &squared);
    return cgalPoint(hints_[index]);
  }
  double distance(const glm::dvec3& p) const {
    return std::sqrt(tree_.tree.squared_distance(cgalPoint(p), hint(p)));
  }

  glm::dvec3 closest(const glm::dvec3& p) const {
    const auto q = tree_.tree.closest_point(cgalPoint(p), hint(p));
    return {CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
  }

  CgalTriangleTree tree_;
  std::vector<glm::dvec3> hints_;  // the triangles' first vertices, each once
  PointList cloud_{hints_};
  std::unique_ptr<PointTree> hintTree_;
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

std::vector<glm::dvec3> usedVerticesOf(const TriangleMesh& mesh) {
  std::vector<char> used(mesh.positions.size(), 0);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) used[v] = 1;
  std::vector<glm::dvec3> vertices;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    if (used[v]) vertices.push_back(mesh.positions[v]);
  return vertices;
}

std::vector<glm::dvec3> samplePositions(const TriangleMesh& mesh, std::size_t count,
                                        std::uint64_t seed) {
  std::vector<glm::dvec3> points;
  const std::vector<SurfaceSample> samples = sampleSurface(mesh, count, seed);
  points.reserve(samples.size());
  for (const SurfaceSample& s : samples) points.push_back(s.position);
  return points;
}

// The samples' distances, summed in index order (the mean is the same bit for bit however the
// queries were split) and their maximum.
OneSide sampleSide(const std::vector<double>& distances) {
  OneSide side;
  double sum = 0.0;
  for (double d : distances) {
    sum += d;
    side.max = std::max(side.max, d);
  }
  side.mean = distances.empty() ? 0.0 : sum / static_cast<double>(distances.size());
  return side;
}

// Samples of `from` (and its used vertices, for the maximum) measured to `to`.
OneSide measureSide(const TriangleMesh& from, const SurfaceDistanceQuery& to, std::size_t count,
                    std::uint64_t seed) {
  const std::vector<glm::dvec3> samples = samplePositions(from, count, seed);
  const std::vector<glm::dvec3> vertices = usedVerticesOf(from);
  OneSide side = sampleSide(pointDistances(samples, to));
  for (double d : pointDistances(vertices, to)) side.max = std::max(side.max, d);
  return side;
}

using SampleTree = PointTree;

// Relative slack on the bound that skips a vertex: the distances are rounded, the triangle
// inequality is not.
constexpr double kBoundSlack = 1e-9;

}  // namespace

struct MeasuredSurface::Samples {
  std::size_t count = 0;
  std::uint64_t seed = 0;
  std::vector<glm::dvec3> points;
  std::vector<std::uint32_t> nearest;  // per used vertex: its nearest sample
  std::vector<double> gap;             // and how far that sample lies from it
};

struct MeasuredSurface::Cache {
  std::mutex mutex;
  std::vector<std::shared_ptr<const Samples>> recent;  // most recent last
};

MeasuredSurface::MeasuredSurface(const TriangleMesh& mesh, const char* which)
    : mesh_(mesh),
      query_(mesh, which),
      diagonal_(boundingDiagonal(mesh)),
      vertices_(usedVerticesOf(mesh)),
      cache_(std::make_unique<Cache>()) {}

MeasuredSurface::~MeasuredSurface() = default;

std::shared_ptr<const MeasuredSurface::Samples> MeasuredSurface::samples(std::size_t count,
                                                                         std::uint64_t seed) const {
  // A fit measures with a few counts and seeds (the start's choice, a probe, its own, the rings').
  constexpr std::size_t kKept = 8;
  {
    const std::lock_guard lock(cache_->mutex);
    for (const auto& kept : cache_->recent)
      if (kept->count == count && kept->seed == seed) return kept;
  }
  auto made = std::make_shared<Samples>();
  made->count = count;
  made->seed = seed;
  made->points = samplePositions(mesh_, count, seed);
  made->nearest.resize(vertices_.size());
  made->gap.resize(vertices_.size(), std::numeric_limits<double>::infinity());
  if (!made->points.empty()) {
    const PointList cloud{made->points};
    const SampleTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices_.size(), 1024),
                      [&](const auto& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          const double query[3] = {vertices_[i].x, vertices_[i].y, vertices_[i].z};
                          std::uint32_t index = 0;
                          double squared = 0.0;
                          tree.knnSearch(query, 1, &index, &squared);
                          made->nearest[i] = index;
                          made->gap[i] = glm::length(vertices_[i] - made->points[index]);
                        }
                      });
  }
  const std::lock_guard lock(cache_->mutex);
  cache_->recent.push_back(made);
  if (cache_->recent.size() > kKept) cache_->recent.erase(cache_->recent.begin());
  return made;
}

namespace {

// Hausdorff and Chamfer from each side's farthest and mean.
SurfaceDistance bothSides(const OneSide& fromA, const OneSide& fromB, double diagonal) {
  SurfaceDistance result;
  result.fromAMax = fromA.max;
  result.fromAMean = fromA.mean;
  result.fromBMax = fromB.max;
  result.fromBMean = fromB.mean;
  result.hausdorff = std::max(fromA.max, fromB.max);
  result.chamfer = 0.5 * (fromA.mean + fromB.mean);
  result.diagonal = diagonal;
  return result;
}

}  // namespace

SurfaceDistance surfaceDistance(const TriangleMesh& a, const TriangleMesh& b, std::size_t samples,
                                std::uint64_t seed) {
  const SurfaceDistanceQuery toA(a, "first"), toB(b, "second");
  const OneSide fromA = measureSide(a, toB, samples, seed);
  const OneSide fromB = measureSide(b, toA, samples, seed + 1);
  return bothSides(fromA, fromB, boundingDiagonal(b));
}

SurfaceDistance surfaceDistance(const TriangleMesh& a, const MeasuredSurface& b,
                                std::size_t samples, std::uint64_t seed) {
  const SurfaceDistanceQuery toA(a, "first");
  const OneSide fromA = measureSide(a, b.query(), samples, seed);
  const std::shared_ptr<const MeasuredSurface::Samples> own = b.samples(samples, seed + 1);
  const std::vector<double> sampleDistances = pointDistances(own->points, toA);
  OneSide fromB = sampleSide(sampleDistances);
  // A vertex lies at most its nearest sample's distance plus their gap from A: only those whose
  // bound passes the samples' farthest can raise it (a few near where B is farthest from A).
  const double bar = fromB.max;
  std::vector<glm::dvec3> beyond;
  const std::vector<glm::dvec3>& vertices = b.usedVertices();
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const double bound = sampleDistances.empty() ? std::numeric_limits<double>::infinity()
                                                 : sampleDistances[own->nearest[i]] + own->gap[i];
    if (!(bound * (1.0 + kBoundSlack) < bar)) beyond.push_back(vertices[i]);
  }
  for (double d : pointDistances(beyond, toA)) fromB.max = std::max(fromB.max, d);
  return bothSides(fromA, fromB, b.diagonal());
}

}  // namespace curvefold
