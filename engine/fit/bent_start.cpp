#include "engine/fit/bent_start.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>
#include <glm/geometric.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {
namespace {

// A profile flatter than this (its curvature times the target's size) is no bend: a flat
// sheet's cross serves there.
constexpr double kLeastBend = 0.05;
// A profile whose arc is under this many times its reach is no steep saddle's: the flat square's
// cross reaches its ends, and a bent square chosen there by its first step ended farther
// (saddle_disk, arc 1.05 times its reach: 13.6% Hausdorff against the flat square's 4.38%).
constexpr double kSteep = 1.3;

// Arc length of w = curvature s^2 + slope s over [from, to].
double parabolaArc(double curvature, double slope, double from, double to) {
  constexpr int kSteps = 512;
  double length = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double s0 = from + (to - from) * i / kSteps, s1 = from + (to - from) * (i + 1) / kSteps;
    const double w0 = curvature * s0 * s0 + slope * s0, w1 = curvature * s1 * s1 + slope * s1;
    length += std::hypot(s1 - s0, w1 - w0);
  }
  return length;
}

std::string vectorText(const glm::dvec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.3g, %.3g, %.3g)", v.x, v.y, v.z);
  return text;
}

}  // namespace

std::vector<PlacedStart> bentStarts(const std::vector<SurfaceSample>& samples,
                                    const std::string& kind, double mostPaper) {
  std::vector<PlacedStart> out;
  if (samples.size() < 10 || (kind != "square" && kind != "rectangle")) return out;
  const PrincipalAxes frame = principalAxes(samples);
  const glm::dvec3 normal = frame.axes[0], u = frame.axes[2], v = frame.axes[1];
  // The quadric over the plane of the two larger axes, in normal equations (6 x 6).
  Eigen::Matrix<double, 6, 6> normalMatrix = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> right = Eigen::Matrix<double, 6, 1>::Zero();
  double size = 0.0;
  for (const SurfaceSample& sample : samples) {
    const glm::dvec3 d = sample.position - frame.centroid;
    const double su = glm::dot(d, u), sv = glm::dot(d, v);
    Eigen::Matrix<double, 6, 1> row;
    row << su * su, su * sv, sv * sv, su, sv, 1.0;
    normalMatrix += row * row.transpose();
    right += row * glm::dot(d, normal);
    size = std::max(size, std::hypot(su, sv));
  }
  if (!(size > 0.0)) return out;
  const Eigen::Matrix<double, 6, 1> q = normalMatrix.ldlt().solve(right);
  Eigen::Matrix2d hessian;
  hessian << 2 * q(0), q(1), q(1), 2 * q(2);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> curvatures(hessian);
  const int strongest =
      std::abs(curvatures.eigenvalues()(1)) >= std::abs(curvatures.eigenvalues()(0)) ? 1 : 0;
  // The quadric at a point (u, v) of the plane.
  auto height = [&](double su, double sv) {
    return q(0) * su * su + q(1) * su * sv + q(2) * sv * sv + q(3) * su + q(4) * sv + q(5);
  };
  for (const int which : {strongest, 1 - strongest}) {
    const Eigen::Vector2d direction = curvatures.eigenvectors().col(which);
    const glm::dvec3 along = glm::normalize(direction(0) * u + direction(1) * v);
    const glm::dvec3 across = glm::normalize(glm::cross(normal, along));
    const glm::dvec2 a(glm::dot(along, u), glm::dot(along, v)),
        b(glm::dot(across, u), glm::dot(across, v));
    // The quadric's lines through the centroid along and across: w(s, 0) and w(0, t), each a
    // parabola (curvature, slope); its offset F.
    const double f = q(5);
    const double curvature = 0.5 * curvatures.eigenvalues()(which);
    const double slope = q(3) * a.x + q(4) * a.y;
    const double acrossSlope = q(3) * b.x + q(4) * b.y;
    const double acrossCurvature = height(b.x, b.y) - acrossSlope - f;  // w(0, 1) less its line
    if (!(std::abs(curvature) * size > kLeastBend)) continue;
    double sLo = 1e300, sHi = -1e300, tLo = 1e300, tHi = -1e300;
    for (const SurfaceSample& sample : samples) {
      const glm::dvec3 d = sample.position - frame.centroid;
      sLo = std::min(sLo, glm::dot(d, along));
      sHi = std::max(sHi, glm::dot(d, along));
      tLo = std::min(tLo, glm::dot(d, across));
      tHi = std::max(tHi, glm::dot(d, across));
    }
    if (!(sHi > sLo) || !(tHi > tLo)) continue;
    const double alongArc = parabolaArc(curvature, slope, sLo, sHi);
    if (alongArc < kSteep * (sHi - sLo)) continue;
    const double acrossArc = parabolaArc(acrossCurvature, acrossSlope, tLo, tHi);
    if (alongArc * acrossArc > mostPaper) continue;
    const bool square = kind == "square";
    const double rulings = square ? std::max(alongArc, acrossArc) : acrossArc;
    if (square && alongArc < rulings) {
      // The profile widened about its middle until its arc is the square's side.
      const double middle = 0.5 * (sLo + sHi);
      double lo = 1.0, hi = 4.0;
      for (int i = 0; i < 40; ++i) {
        const double k = 0.5 * (lo + hi);
        (parabolaArc(curvature, slope, middle + k * (sLo - middle), middle + k * (sHi - middle)) <
                 rulings
             ? lo
             : hi) = k;
      }
      sLo = middle + hi * (sLo - middle);
      sHi = middle + hi * (sHi - middle);
    }
    Sheet sheet = sweptParabola(curvature, slope, sLo, sHi, rulings);
    // The development's side along the profile is its chords' length, a hair under the arc: a
    // square's rulings are cut to it, so its development is a square to the bit (the second
    // sheet's chords are the third's: the count of samples along no longer changes).
    for (int i = 0; square && i < 3; ++i) {
      const DevelopmentBounds bounds = developmentBounds(sheet);
      const double side = bounds.high.x - bounds.low.x;
      if (std::abs(side - (bounds.high.y - bounds.low.y)) <= 1e-12 * side) break;
      sheet = sweptParabola(curvature, slope, sLo, sHi, side);
    }
    const DevelopmentBounds bounds = developmentBounds(sheet);
    const double width = bounds.high.x - bounds.low.x, depth = bounds.high.y - bounds.low.y;
    // The rulings tilted by the slope along them (the saddle's centre line rises across), from
    // the middle of the target's extent across, the profile lifted by the quadric's offset.
    const glm::dvec3 ruling = glm::normalize(across + acrossSlope * normal);
    const glm::dvec3 up = glm::cross(along, ruling);
    const glm::dvec3 origin = frame.centroid + (0.5 * (tLo + tHi) - 0.5 * depth) * ruling + f * up;
    for (glm::dvec3& p : sheet.positions) p = origin + p.x * along + p.y * ruling + p.z * up;
    char text[200];
    std::snprintf(text, sizeof text,
                  "bent along %s into the profile %.4g s^2 %+.4g s, ruled along %s from %s",
                  vectorText(along).c_str(), curvature, slope, vectorText(ruling).c_str(),
                  vectorText(origin).c_str());
    out.push_back(
        {square ? "bent_square" : "bent_rectangle",
         square ? SurfaceParameters{{"size", width}, {"curvature", curvature}}
                : SurfaceParameters{{"width", width}, {"height", depth}, {"curvature", curvature}},
         text, std::move(sheet)});
  }
  return out;
}

}  // namespace curvefold
