// How far two surfaces lie apart (issue 27), as a user can check it: area-uniform samples of each
// (surface_samples.hpp), each measured to the other surface exactly (the closest point on its
// triangles, by CGAL's AABB tree). The two-sided Hausdorff distance is the largest of those
// distances (every vertex of each mesh is measured too, where a maximum often lies: a corner); the
// Chamfer distance is the mean of the two one-sided means.
//
// Known limits: the Hausdorff distance is a lower bound (a sample may miss the farthest point by
// up to the sample spacing, sqrt(area / samples)); both need surfaces with area.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

// A mesh that cannot be measured: no triangle with area.
class DegenerateMesh : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct SurfaceDistance {
  double fromAMax = 0.0, fromAMean = 0.0;  // samples of A to B
  double fromBMax = 0.0, fromBMean = 0.0;  // samples of B to A
  double hausdorff = 0.0;                  // max of the two maxima
  double chamfer = 0.0;                    // mean of the two means
  double diagonal = 0.0;                   // B's bounding-box diagonal: what "relative" divides by
  double relativeHausdorff() const { return hausdorff / diagonal; }
  double relativeChamfer() const { return chamfer / diagonal; }
};

inline constexpr std::size_t kDefaultDistanceSamples = 20'000;

// Distances from points to one mesh's surface (the closest point on its triangles with area),
// for many queries; safe to query from several threads. Throws DegenerateMesh (naming `which`)
// for a mesh without area or with a vertex too far out to measure (unmeasurableVertex).
class SurfaceDistanceQuery {
 public:
  SurfaceDistanceQuery(const TriangleMesh& mesh, const char* which = "first");
  ~SurfaceDistanceQuery();
  SurfaceDistanceQuery(const SurfaceDistanceQuery&) = delete;
  SurfaceDistanceQuery& operator=(const SurfaceDistanceQuery&) = delete;
  double distance(const glm::dvec3& p) const;
  glm::dvec3 closestPoint(const glm::dvec3& p) const;  // the surface's point nearest p

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

// The triangles SurfaceDistanceQuery has put in trees in this process so far: what measuring has
// indexed, for tests and benchmarks (a target indexed once per fit, not once per measure).
std::uint64_t distanceTreeTriangles();

// Each point's distance to the query's surface (a picture's per-vertex field: a fitted sheet's
// vertices to its target), on all cores; the same result for any thread count.
std::vector<double> pointDistances(std::span<const glm::dvec3> points,
                                   const SurfaceDistanceQuery& to);

// A against B (B is the reference, a fit's target). Both halves run on all cores; the result is
// the same for the same samples and seed. Throws DegenerateMesh naming "first" or "second".
SurfaceDistance surfaceDistance(const TriangleMesh& a, const TriangleMesh& b,
                                std::size_t samples = kDefaultDistanceSamples,
                                std::uint64_t seed = 1);

// A reference surface measured against many others (a fit's target: every sheet the start's
// choice, the fit and the studio measure): its closest-point tree, its used vertices, and its
// samples with each vertex's nearest sample, made once and shared by every measure against it,
// where surfaceDistance(a, b) makes them anew for each (on a 100k-triangle scan a third of a
// second of CPU a measure, nearly all of it the tree and B's vertices). Made lazily: the
// constructor checks and builds the tree only; the samples of a count and seed at their first
// measure (the last few kept). `mesh` must outlive it. Safe to measure against from several
// threads. Throws DegenerateMesh (naming `which`) as SurfaceDistanceQuery does.
class MeasuredSurface {
 public:
  explicit MeasuredSurface(const TriangleMesh& mesh, const char* which = "second");
  ~MeasuredSurface();
  MeasuredSurface(const MeasuredSurface&) = delete;
  MeasuredSurface& operator=(const MeasuredSurface&) = delete;

  const TriangleMesh& mesh() const { return mesh_; }
  const SurfaceDistanceQuery& query() const { return query_; }
  double diagonal() const { return diagonal_; }

  struct Samples;  // samples of one count and seed, and each used vertex's nearest
  std::shared_ptr<const Samples> samples(std::size_t count, std::uint64_t seed) const;
  const std::vector<glm::dvec3>& usedVertices() const { return vertices_; }

 private:
  const TriangleMesh& mesh_;
  SurfaceDistanceQuery query_;
  double diagonal_ = 0.0;
  std::vector<glm::dvec3> vertices_;
  struct Cache;
  std::unique_ptr<Cache> cache_;
};

// The same as surfaceDistance(a, b.mesh(), samples, seed), bit for bit, with B's tree and samples
// made once. B's vertices are measured only where they could lie farther than B's farthest sample
// (a vertex's distance is at most its nearest sample's plus the two's spacing): the same maximum.
SurfaceDistance surfaceDistance(const TriangleMesh& a, const MeasuredSurface& b,
                                std::size_t samples = kDefaultDistanceSamples,
                                std::uint64_t seed = 1);

}  // namespace curvefold
