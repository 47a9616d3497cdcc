// Principal moments (principal_moments.hpp): the spread of a known box of points and of a
// cylinder's area, whose eigenvectors the fit and the render library take as principal axes.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/geometry/principal_moments.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

void expectNear(const glm::dmat3& a, const glm::dmat3& b, double tolerance) {
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      EXPECT_NEAR(a[c][r], b[c][r], tolerance) << "[" << c << "][" << r << "]";
}

// A 3 x 3 x 3 grid of a box with half-sides 3, 2 and 1, turned and moved: its scatter is
// R diag(9 * 2 * side^2) R^T about its middle (each side's -1, 0, 1 give 2, times the 9 points
// of each layer).
TEST(PrincipalMoments, ABoxOfPointsSpreadsAlongItsTurnedSides) {
  const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3))));
  const glm::dvec3 middle(0.5, -2.0, 4.0), half(3.0, 2.0, 1.0);
  std::vector<glm::dvec3> points;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) points.push_back(middle + turn * (half * glm::dvec3(i, j, k)));
  const PointMoments m = pointMoments(points);
  EXPECT_EQ(m.weight, 27.0);
  EXPECT_NEAR(glm::distance(m.centre, middle), 0.0, 1e-12);
  const glm::dmat3 along(glm::dvec3(18.0 * half.x * half.x, 0, 0),
                         glm::dvec3(0, 18.0 * half.y * half.y, 0),
                         glm::dvec3(0, 0, 18.0 * half.z * half.z));
  expectNear(m.scatter, turn * along * glm::transpose(turn), 1e-11);
  // About a given point: the scatter grows by the count times the offset's outer product.
  const glm::dvec3 offset(1.0, 0.0, 0.0);
  const PointMoments about = pointMoments(points, {}, middle + offset);
  EXPECT_EQ(about.centre, middle + offset);
  expectNear(about.scatter, m.scatter + 27.0 * glm::outerProduct(offset, offset), 1e-11);
}

// A weight of 3 counts as three copies of the point: the weighted mean and scatter are those of
// the points repeated.
TEST(PrincipalMoments, AWeightCountsAsThatManyCopies) {
  const std::vector<glm::dvec3> points{{0, 0, 0}, {4, 0, 0}, {0, 2, 1}, {1, -1, 3}};
  const std::vector<double> weights{3.0, 1.0, 2.0, 1.0};
  std::vector<glm::dvec3> copies;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int n = 0; n < int(weights[i]); ++n) copies.push_back(points[i]);
  const PointMoments weighted = pointMoments(points, weights), repeated = pointMoments(copies);
  EXPECT_EQ(weighted.weight, 7.0);
  EXPECT_NEAR(glm::distance(weighted.centre, repeated.centre), 0.0, 1e-12);
  expectNear(weighted.scatter, repeated.scatter, 1e-12);
  // In the plane, unweighted: (0, 0) and (2, 0) spread 2 along x about (1, 0).
  const PointMoments2 flat = pointMoments(std::vector<glm::dvec2>{{0, 0}, {2, 0}});
  EXPECT_EQ(flat.centre, glm::dvec2(1, 0));
  EXPECT_EQ(flat.scatter, glm::dmat2(2, 0, 0, 0));
}

// The catalogue's cylinder (radius 0.045, height 0.21 about y, a 48-sided prism): its area is the
// prism's, its covariance exact for that prism (triangles as uniform sheets, not points at their
// centroids): along the axis height^2 / 12, across it the mean square of a side's x,
// (d^2 + l^2 / 3) / 2 with d the side's distance from the axis and l its half-length.
TEST(PrincipalMoments, ACylindersAreaSpreadsAsItsPrism) {
  const Sheet sheet = makeSurface("cylinder");
  const double r = 0.045, h = 0.21, sides = 48.0;
  const double d = r * std::cos(std::numbers::pi / sides),
               l = r * std::sin(std::numbers::pi / sides);
  const AreaMoments m = areaMoments(sheet);
  EXPECT_NEAR(m.area, 2.0 * sides * l * h, 1e-12);
  EXPECT_NEAR(glm::length(m.centre), 0.0, 1e-12);
  const double across = 0.5 * (d * d + l * l / 3.0);
  expectNear(m.covariance,
             glm::dmat3(glm::dvec3(across, 0, 0), glm::dvec3(0, h * h / 12.0, 0),
                        glm::dvec3(0, 0, across)),
             1e-12);
  // Triangles of no area are left out; none at all leave zero moments.
  Sheet degenerate = sheet;
  degenerate.triangles.push_back({VertexIndex(0), VertexIndex(0), VertexIndex(1)});
  EXPECT_EQ(areaMoments(degenerate).area, m.area);
  EXPECT_EQ(areaMoments(Sheet{}).area, 0.0);
  EXPECT_EQ(areaMoments(Sheet{}).covariance, glm::dmat3(0.0));
}

}  // namespace
}  // namespace curvefold
