// The first and second moments of a point set or of a sheet's area: the centre and the spread
// about it whose eigenvectors are the principal axes (a sheet's normal, a tube's axis, the long
// side of a pleat). The geometry core has no eigensolver, so the caller solves the symmetric
// matrix (Eigen's SelfAdjointEigenSolver in the fit and the render library); every entry is
// summed in the order the callers' hand-written loops did, so their results stay bit-identical.
#pragma once

#include <optional>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

// Weighted points' moments.
//   centre   the weighted mean (sum w p / sum w), or the point given as `about`
//   scatter  sum over the points of w d d^T with d = p - centre, full (not divided by the weight:
//            the covariance is scatter / weight); entry [c][r] is the sum of (w d[r]) d[c]
//   weight   sum w (the count when unweighted)
struct PointMoments {
  glm::dvec3 centre{0.0};
  glm::dmat3 scatter{0.0};
  double weight = 0.0;
};
struct PointMoments2 {
  glm::dvec2 centre{0.0};
  glm::dmat2 scatter{0.0};
  double weight = 0.0;
};

// Inputs:
//   points   the points (samples, vertices, triangles' centroids or normals)
//   weights  one per point (areas), or empty for 1 each
//   about    the centre to spread about (a bounding box's middle), or none for the weighted mean
// Outputs: the moments above; with no points (or a zero total weight and no `about`) the centre
// is the origin and the scatter zero.
// Limits: weights are not checked (a negative one subtracts); one pass over the points each for
// the mean and the scatter.
PointMoments pointMoments(const std::vector<glm::dvec3>& points,
                          const std::vector<double>& weights = {},
                          const std::optional<glm::dvec3>& about = std::nullopt);
// The same in the plane (a profile's (height, radius) points), unweighted, about the mean.
PointMoments2 pointMoments(const std::vector<glm::dvec2>& points);

// A sheet's area moments: each triangle a uniform sheet of its area, its second moment exact,
// (a a^T + b b^T + c c^T + s s^T) / 12 times its area with s = a + b + c.
//   centre      the area centroid
//   covariance  second moment / area - centre centre^T (divided by the area, unlike a scatter)
//   area        the sum of the areas; triangles of no area are left out
// Limits: with no area (no triangles, all degenerate) centre and covariance are zero; the second
// moment is taken about the origin, so a sheet far from it (further than its size by 1e7 or more)
// loses digits to cancellation.
struct AreaMoments {
  glm::dvec3 centre{0.0};
  glm::dmat3 covariance{0.0};
  double area = 0.0;
};
AreaMoments areaMoments(const Sheet& sheet);

}  // namespace curvefold
