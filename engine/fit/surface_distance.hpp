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

// Each point's distance to the query's surface (a picture's per-vertex field: a fitted sheet's
// vertices to its target), on all cores; the same result for any thread count.
std::vector<double> pointDistances(std::span<const glm::dvec3> points,
                                   const SurfaceDistanceQuery& to);

// A against B (B is the reference, a fit's target). Both halves run on all cores; the result is
// the same for the same samples and seed. Throws DegenerateMesh naming "first" or "second".
SurfaceDistance surfaceDistance(const TriangleMesh& a, const TriangleMesh& b,
                                std::size_t samples = kDefaultDistanceSamples,
                                std::uint64_t seed = 1);

}  // namespace curvefold
