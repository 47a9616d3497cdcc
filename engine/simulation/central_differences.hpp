// Second derivatives of a function of four points by central differences of its exact gradient,
// for the static solver's exact Hessian (static_solver.cpp: a hinge's angle, a contact pair's
// distance), where no closed form is written.
//
// Input: the four points, the step h (in metres) and the gradient: gradientOf(points, out) sets
// out to d f / d points and returns false where f is not defined there. Output: second[p][q], the
// 3x3 block of points p and q (column c: d gradient[p] / d points[q][c]), not symmetrized; false
// where the gradient was not defined at some shifted point (second then undefined). Cost: 24
// gradients.
//
// Each difference is divided by the width the coordinate moved as rounded, (x + h) - (x - h),
// not by 2h: x +- h rounds to the last place of x, and with h = 1e-6 of a 5 mm edge at 0.13 m from
// the origin the two widths differ by up to 3e-9 of 2h, an error of that share in every entry of
// the Hessian (traditionalCrane at 75% of 25:100:4 held at residual 1.9e-7 by it, issue 39); with
// a contact's 1e-9 m step, by up to 1.4e-8.
#pragma once

#include <array>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace curvefold {

template <class GradientOf>
bool centralDifferenceHessian(std::array<glm::dvec3, 4> points, double step,
                              GradientOf&& gradientOf,
                              std::array<std::array<glm::dmat3, 4>, 4>& second) {
  std::array<glm::dvec3, 4> plus{}, minus{};
  for (int q = 0; q < 4; ++q)
    for (int c = 0; c < 3; ++c) {
      const double kept = points[q][c];
      const double up = kept + step, down = kept - step;
      points[q][c] = up;
      const bool upDefined = gradientOf(points, plus);
      points[q][c] = down;
      const bool downDefined = gradientOf(points, minus);
      points[q][c] = kept;
      if (!upDefined || !downDefined) return false;
      for (int p = 0; p < 4; ++p)
        for (int r = 0; r < 3; ++r) second[p][q][c][r] = (plus[p][r] - minus[p][r]) / (up - down);
    }
  return true;
}

}  // namespace curvefold
