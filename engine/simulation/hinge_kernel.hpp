// The hinge's signed dihedral angle and its gradient, inlined where the forces are computed
// (bar_hinge_model.cpp's elementForces, dynamic_solver.cpp's step): shared so both give the same
// bits. Inputs: the hinge's four positions (a -> b the edge as its left triangle (a, b, c) runs
// it, right triangle (b, a, d)) and the last known angle; output: the angle unwrapped to lie
// within pi of it and d(angle)/d(a, b, c, d). Limits: a degenerate triangle gives the previous
// angle and a zero gradient.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace curvefold::hinge_kernel {

// atan2 by Cephes' atan (S. L. Moshier, Cephes Math Library, atan.c: range reduction to
// |x| <= 0.66 and a rational approximation of degree 4/5, within 2 ulp of std::atan2 over random
// tests), inlined: the libm call was a fifth of a dynamic step, and this one gives the same bits
// on every machine (libm picks an FMA variant by CPU).
inline double atanOfNonNegative(double x) {
  constexpr double kMoreBits = 6.123233995736765886130e-17;  // pi/2 - double(pi/2)
  double base = 0.0, more = 0.0;
  if (x > 2.41421356237309504880) {  // tan(3 pi / 8)
    base = std::numbers::pi / 2;
    more = kMoreBits;
    x = -1.0 / x;
  } else if (x > 0.66) {
    base = std::numbers::pi / 4;
    more = 0.5 * kMoreBits;
    x = (x - 1.0) / (x + 1.0);
  }
  const double z = x * x;
  const double p = (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z -
                     7.500855792314704667340e1) *
                        z -
                    1.228866684490136173410e2) *
                       z -
                   6.485021904942025371773e1;
  const double q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z +
                     4.328810604912902668951e2) *
                        z +
                    4.853903996359136964868e2) *
                       z +
                   1.945506571482613964425e2;
  return base + ((x * z * p / q + more) + x);
}

inline double atan2Cephes(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  if (ax == 0.0 && ay == 0.0) return 0.0;
  double angle =
      ay <= ax ? atanOfNonNegative(ay / ax) : std::numbers::pi / 2 - atanOfNonNegative(ax / ay);
  if (x < 0.0) angle = std::numbers::pi - angle;
  return y < 0.0 ? -angle : angle;
}

// previous + (raw - previous) wrapped to [-pi, pi]: the remainder only when it wraps (it is the
// step's costliest call otherwise, and the same bits: remainder returns |d| <= pi unchanged).
inline double unwrapAgainst(double raw, double previous) {
  double change = raw - previous;
  if (change > std::numbers::pi || change < -std::numbers::pi)
    change = std::remainder(change, 2.0 * std::numbers::pi);
  return previous + change;
}

// The dynamic step's kernel, inlined into elementForces.
[[gnu::always_inline]] inline double angleWithGradient(const glm::dvec3& a, const glm::dvec3& b,
                                                       const glm::dvec3& c, const glm::dvec3& d,
                                                       double previous,
                                                       std::array<glm::dvec3, 4>& gradient) {
  const glm::dvec3 edge = b - a;
  const glm::dvec3 n1 = glm::cross(edge, c - a);
  const glm::dvec3 n2 = glm::cross(a - b, d - b);
  const double n1n1 = glm::dot(n1, n1), n2n2 = glm::dot(n2, n2), ee = glm::dot(edge, edge);
  if (n1n1 == 0.0 || n2n2 == 0.0 || ee == 0.0) {
    gradient = {};
    return previous;
  }
  const double length = std::sqrt(ee);
  const double raw = atan2Cephes(-glm::dot(glm::cross(n1, n2), edge) / length, glm::dot(n1, n2));
  const glm::dvec3 gc = n1 * (length / n1n1);
  const glm::dvec3 gd = n2 * (length / n2n2);
  const double tc = glm::dot(c - a, edge) / ee;
  const double td = glm::dot(d - a, edge) / ee;
  gradient = {-(1.0 - tc) * gc - (1.0 - td) * gd, -tc * gc - td * gd, gc, gd};
  return unwrapAgainst(raw, previous);
}

}  // namespace curvefold::hinge_kernel
