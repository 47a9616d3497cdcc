// The bar-and-hinge model's element kernels, inlined where the forces are computed
// (bar_hinge_model.cpp's elementForces and hingeAngle, dynamic_solver.cpp's step): shared so all
// give the same bits.
//
// Hinge: inputs the hinge's four positions (a -> b the edge as its left triangle (a, b, c) runs
// it, right triangle (b, a, d)) and the last known angle; output the signed dihedral angle
// (positive valley) unwrapped to lie within pi of it and d(angle)/d(a, b, c, d). Bar: the force
// on its first end (the second takes the opposite). Limits: a degenerate triangle gives the
// previous angle and a zero gradient; a bar of zero length has no force.
//
// Cost (the dynamic step is mostly these): a hinge takes one square root and three divisions
// (one reciprocal serves the gradient's three; the angle's atan2 takes two), a bar one of each.
// The angle is atan2 of the normals' sine and cosine without normalizing either: with
// e = b - a, u = c - a, w = d - a, n1 = e x u, n2 = w x e, (n1 x n2) . e = -det(e, u, w) |e|^2,
// so |n1| |n2| sin = |e| (n1 . w) and |n1| |n2| cos = n1 . n2.
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
// on every machine (libm picks an FMA variant by CPU). Written without branches (each choice a
// select, the reduced argument from |y| and |x| in one division: (|y| - |x|) / (|y| + |x|) rather
// than (t - 1) / (t + 1) of t = |y| / |x|), so a loop over hinges vectorizes; (0, 0) gives 0.
[[gnu::always_inline]] inline double atan2Cephes(double y, double x) {
  constexpr double kMoreBits = 6.123233995736765886130e-17;  // pi/2 - double(pi/2)
  const double ax = std::abs(x), ay = std::abs(y);
  const bool steep = ay > 2.41421356237309504880 * ax;  // tan(3 pi / 8)
  const bool middle = ay > 0.66 * ax;                   // and not steep
  // Both computed whatever the choice: an operation under a condition keeps a loop scalar.
  const double difference = ay - ax, sum = ay + ax;
  double numerator = middle ? difference : ay, denominator = middle ? sum : ax;
  double base = middle ? std::numbers::pi / 4 : 0.0, more = middle ? 0.5 * kMoreBits : 0.0;
  numerator = steep ? -ax : numerator;
  denominator = steep ? ay : denominator;
  base = steep ? std::numbers::pi / 2 : base;
  more = steep ? kMoreBits : more;
  const double t = numerator / (denominator > 0.0 ? denominator : 1.0);
  const double z = t * t;
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
  double angle = base + ((t * z * p / q + more) + t);
  angle = x < 0.0 ? std::numbers::pi - angle : angle;
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

// The hinge's angle alone (the same bits as angleWithGradient's).
[[gnu::always_inline]] inline double angle(const glm::dvec3& a, const glm::dvec3& b,
                                           const glm::dvec3& c, const glm::dvec3& d,
                                           double previous) {
  const glm::dvec3 edge = b - a, w = d - a;
  const glm::dvec3 n1 = glm::cross(edge, c - a);
  const glm::dvec3 n2 = glm::cross(w, edge);
  const double n1n1 = glm::dot(n1, n1), n2n2 = glm::dot(n2, n2), ee = glm::dot(edge, edge);
  if (n1n1 == 0.0 || n2n2 == 0.0 || ee == 0.0) return previous;
  return unwrapAgainst(atan2Cephes(std::sqrt(ee) * glm::dot(n1, w), glm::dot(n1, n2)), previous);
}

// Products of three squared norms this far inside double's range take one reciprocal; outside
// it (edges under 1e-25 or over 1e25 of the unit) each is divided on its own.
constexpr double kSmallestProduct = 1e-290, kLargestProduct = 1e290;

// The hinge's angle and gradient without a branch (a loop over hinges vectorizes it), for the
// usual hinge: returns false, its outputs then unusable, where angleWithGradient must take its
// careful path (a degenerate triangle, squared norms whose product leaves kSmallestProduct ..
// kLargestProduct, an angle that wraps past pi from the previous one).
[[gnu::always_inline]] inline bool angleWithGradientUsual(const glm::dvec3& a, const glm::dvec3& b,
                                                          const glm::dvec3& c, const glm::dvec3& d,
                                                          double previous, double& angle,
                                                          std::array<glm::dvec3, 4>& gradient) {
  const glm::dvec3 edge = b - a, u = c - a, w = d - a;
  const glm::dvec3 n1 = glm::cross(edge, u);
  const glm::dvec3 n2 = glm::cross(w, edge);
  const double n1n1 = glm::dot(n1, n1), n2n2 = glm::dot(n2, n2), ee = glm::dot(edge, edge);
  const double length = std::sqrt(ee);
  const double change = atan2Cephes(length * glm::dot(n1, w), glm::dot(n1, n2)) - previous;
  angle = previous + change;
  // 1 / n1n1, 1 / n2n2 and 1 / ee from one reciprocal of their product (which is 0 for a
  // degenerate triangle).
  const double n1n2 = n1n1 * n2n2, product = n1n2 * ee;
  // (& rather than &&: no branch)
  const bool usual = (product > kSmallestProduct) & (product < kLargestProduct) &
                     (change <= std::numbers::pi) & (change >= -std::numbers::pi);
  const double r = 1.0 / (usual ? product : 1.0);
  // A wing moving along its face's normal turns the face by 1 / its height (valley positive).
  const glm::dvec3 gc = n1 * (length * ((n2n2 * ee) * r));
  const glm::dvec3 gd = n2 * (length * ((n1n1 * ee) * r));
  // The edge's ends share the rest so the gradient is blind to translation and rotation.
  const double tc = glm::dot(u, edge) * (n1n2 * r);
  const double td = glm::dot(w, edge) * (n1n2 * r);
  gradient = {-(1.0 - tc) * gc - (1.0 - td) * gd, -tc * gc - td * gd, gc, gd};
  return usual;
}

// The hinge's angle unwrapped against `previous` and its gradient: angleWithGradientUsual's bits
// where it applies, else the same formulas with a division each (0 for a degenerate triangle).
[[gnu::always_inline]] inline double angleWithGradient(const glm::dvec3& a, const glm::dvec3& b,
                                                       const glm::dvec3& c, const glm::dvec3& d,
                                                       double previous,
                                                       std::array<glm::dvec3, 4>& gradient) {
  double usualAngle;
  if (angleWithGradientUsual(a, b, c, d, previous, usualAngle, gradient)) return usualAngle;
  const glm::dvec3 edge = b - a, u = c - a, w = d - a;
  const glm::dvec3 n1 = glm::cross(edge, u);
  const glm::dvec3 n2 = glm::cross(w, edge);
  const double n1n1 = glm::dot(n1, n1), n2n2 = glm::dot(n2, n2), ee = glm::dot(edge, edge);
  if (n1n1 == 0.0 || n2n2 == 0.0 || ee == 0.0) {
    gradient = {};
    return previous;
  }
  const double length = std::sqrt(ee);
  const double raw = atan2Cephes(length * glm::dot(n1, w), glm::dot(n1, n2));
  const glm::dvec3 gc = n1 * (length / n1n1);
  const glm::dvec3 gd = n2 * (length / n2n2);
  const double tc = glm::dot(u, edge) / ee;
  const double td = glm::dot(w, edge) / ee;
  gradient = {-(1.0 - tc) * gc - (1.0 - td) * gd, -tc * gc - td * gd, gc, gd};
  return unwrapAgainst(raw, previous);
}

// A crease may not pass through the flat state to the other side (a mountain folded as a valley),
// nor past its flat-folded state (through the paper): along its side (q = side x angle, side +1
// for a valley, -1 for a mountain) the crease's energy gains 1/2 |wrongSide| q^2 below q = 0 and
// 1/2 |wrongSide| (q - pi)^2 above q = pi, zero between (bar_hinge_model.hpp). wrongSide is the
// signed stiffness of that term (its sign the crease's side; 0: none, as for facets); the
// distance past either bound, signed along the angle, is returned, so that the term's moment
// d/dtheta is wrongSide x it. Without a branch (the hinge loop vectorizes).
[[gnu::always_inline]] inline double wrongSideExcess(double angle, double wrongSide) {
  const double side = wrongSide > 0.0 ? 1.0 : (wrongSide < 0.0 ? -1.0 : 0.0);
  const double q = side * angle;
  const double below = q < 0.0 ? q : 0.0;
  const double above = q > std::numbers::pi ? q - std::numbers::pi : 0.0;
  return below + above;
}

// The hinge energy's moment dE/dtheta: stiffness (angle - target) plus the one-sided term's
// (wrongSideExcess). For wrongSide 0 the same bits as stiffness (angle - target) alone.
[[gnu::always_inline]] inline double hingeMoment(double angle, double target, double stiffness,
                                                 double wrongSide) {
  return stiffness * (angle - target) + wrongSide * wrongSideExcess(angle, wrongSide);
}

// The hinge's energy: 1/2 stiffness (angle - target)^2 and the one-sided term.
inline double hingeEnergy(double angle, double target, double stiffness, double wrongSide) {
  const double error = angle - target, excess = wrongSideExcess(angle, wrongSide);
  return 0.5 * stiffness * error * error + 0.5 * std::abs(wrongSide) * excess * excess;
}

// A bar's force on its first end a (delta = b - a): stiffness (length - rest) plus damping times
// the ends' relative speed along it (dampingTimesSpeed: damping x (vb - va)), along delta.
[[gnu::always_inline]] inline glm::dvec3 barForce(const glm::dvec3& delta,
                                                  const glm::dvec3& relativeVelocity,
                                                  double stiffness, double restLength,
                                                  double damping) {
  // Without a branch (a loop over bars vectorizes it): a bar of zero length selects 0.
  const double squared = glm::dot(delta, delta);
  const bool usual = squared > 0.0;
  const double length = std::sqrt(squared);
  const double inverse = 1.0 / (usual ? length : 1.0);
  const double pull =
      stiffness * (length - restLength) + damping * glm::dot(relativeVelocity, delta) * inverse;
  const double scale = pull * inverse;
  return glm::dvec3(usual ? scale * delta.x : 0.0, usual ? scale * delta.y : 0.0,
                    usual ? scale * delta.z : 0.0);
}

}  // namespace curvefold::hinge_kernel
