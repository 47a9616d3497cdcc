#include "engine/fit/lip_pleats.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>

#include "engine/fit/floor_rings.hpp"
#include "engine/fit/ring_folds.hpp"

namespace curvefold {

namespace {

constexpr double kFlattestTaper = 0.05;
constexpr std::size_t kProfileBins = 32;
// The target must stand out of the cone at its wide end by this much of the cone's radius there.
constexpr double kLeastGap = 0.02;
constexpr double kStartFractions[] = {0.0, 0.2, 0.4};  // of the span where the target stands out
constexpr int kMostSteps = 6;
constexpr double kScales[] = {1.0, 0.6};  // of each step's solved shift (the sheet shortens)
// A step's flap takes at most this much of the way to the next step.
constexpr double kWidestFlap = 0.8;

glm::dvec3 perpendicularTo(const glm::dvec3& a) {
  const glm::dvec3 other = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(other, a));
}

// Least squares radius = r0 + s t over the points, about the line through `point` along `d`.
void fitLine(const std::vector<glm::dvec3>& points, const glm::dvec3& point, const glm::dvec3& d,
             double& r0, double& s, double& lowest, double& highest) {
  double sumT = 0.0, sumR = 0.0, sumTT = 0.0, sumTR = 0.0;
  lowest = 1e300;
  highest = -1e300;
  for (const glm::dvec3& p : points) {
    const double t = glm::dot(p - point, d);
    const double r = glm::length(p - point - t * d);
    sumT += t;
    sumR += r;
    sumTT += t * t;
    sumTR += t * r;
    lowest = std::min(lowest, t);
    highest = std::max(highest, t);
  }
  const auto n = static_cast<double>(points.size());
  const double meanT = sumT / n, meanR = sumR / n, variance = sumTT / n - meanT * meanT;
  s = variance > 0.0 ? (sumTR / n - meanT * meanR) / variance : 0.0;
  r0 = meanR - s * meanT;
}

}  // namespace

std::optional<ConeProfile> coneProfile(const Sheet& sheet, const glm::dvec3& direction) {
  const std::optional<TubeAxis> tube = tubeAbout(sheet, direction, kLipSteepestTaper);
  if (!tube) return std::nullopt;
  ConeProfile cone;
  cone.axis = tube->axis;
  fitLine(sheet.positions, cone.axis.point, cone.axis.direction, cone.radius, cone.slope,
          cone.lowest, cone.highest);
  if (cone.slope < 0.0) {  // the direction toward the wide end
    cone.axis.direction = -cone.axis.direction;
    fitLine(sheet.positions, cone.axis.point, cone.axis.direction, cone.radius, cone.slope,
            cone.lowest, cone.highest);
  }
  if (cone.slope < kFlattestTaper) return std::nullopt;
  return cone;
}

std::vector<std::vector<LipStep>> lipStaircases(const ConeProfile& cone,
                                                const std::vector<SurfaceSample>& targetSamples) {
  const glm::dvec3& c = cone.axis.point;
  const glm::dvec3& d = cone.axis.direction;
  // The target's mean radius by height, over the cone's span.
  const double span = cone.highest - cone.lowest;
  std::vector<double> sum(kProfileBins, 0.0), count(kProfileBins, 0.0);
  for (const SurfaceSample& s : targetSamples) {
    const double t = glm::dot(s.position - c, d);
    const double u = (t - cone.lowest) / span;
    if (u < 0.0 || u >= 1.0) continue;
    const auto bin = static_cast<std::size_t>(u * kProfileBins);
    sum[bin] += glm::length(s.position - c - t * d);
    count[bin] += 1.0;
  }
  const auto heightOf = [&](std::size_t bin) {
    return cone.lowest + span * (static_cast<double>(bin) + 0.5) / kProfileBins;
  };
  const auto coneRadius = [&](double t) { return cone.radius + cone.slope * t; };
  // The target's radius at t: the nearest bin holding samples.
  const auto targetRadius = [&](double t) {
    const double u = std::clamp((t - cone.lowest) / span * kProfileBins - 0.5, 0.0,
                                static_cast<double>(kProfileBins - 1));
    const auto at = static_cast<std::size_t>(std::lround(u));
    for (std::size_t k = 0; k < kProfileBins; ++k)
      for (const std::size_t b : {at + k, at - k})
        if (b < kProfileBins && count[b] > 0.0) return sum[b] / count[b];
    return coneRadius(t);
  };
  // Where the target stands out of the cone toward the wide end: from the widest bin holding
  // samples down to the first where it does not.
  std::size_t top = kProfileBins;
  while (top > 0 && count[top - 1] == 0.0) --top;
  if (top == 0) return {};
  const double wideEnd = heightOf(top - 1);
  if (targetRadius(wideEnd) - coneRadius(wideEnd) < kLeastGap * coneRadius(wideEnd)) return {};
  std::size_t in = top - 1;
  while (in > 0 &&
         (count[in - 1] == 0.0 || targetRadius(heightOf(in - 1)) > coneRadius(heightOf(in - 1))))
    --in;
  const double standsOut = heightOf(in);
  std::vector<std::vector<LipStep>> staircases;
  for (const double fraction : kStartFractions) {
    const double first = standsOut + fraction * (wideEnd - standsOut);
    for (int n = 1; n <= kMostSteps; ++n)
      for (const double scale : kScales) {
        std::vector<LipStep> steps;
        double shifted = 0.0;  // how far the wide part has moved toward the apex so far
        for (int j = 0; j < n; ++j) {
          const double at = first + (wideEnd - first) * j / n;
          const double next = first + (wideEnd - first) * (j + 1) / n;
          const double middle = 0.5 * (at + next);
          // The shift that brings the cone's line to the target's radius at the middle.
          const double wanted =
              scale * ((targetRadius(middle) - cone.radius) / cone.slope - middle);
          double width = 0.5 * (wanted - shifted);
          width = std::min(width, kWidestFlap * (next - at));
          // The part past the crease must be longer than the flap, to be turned back past it.
          const double end = cone.highest - shifted;
          width = std::min(width, 0.45 * (end - at));
          if (!(width > 1e-3 * cone.radius)) continue;
          steps.push_back({at + width, width});
          shifted += 2.0 * width;
        }
        if (!steps.empty()) staircases.push_back(std::move(steps));
      }
  }
  return staircases;
}

Ring lipPleatRing(const ConeProfile& cone, const std::vector<LipStep>& steps) {
  const glm::dvec3& c = cone.axis.point;
  const glm::dvec3& d = cone.axis.direction;
  const glm::dvec3 across = perpendicularTo(d);
  const double rim = cone.radius + cone.slope * cone.highest;
  Ring ring;
  double shifted = 0.0;
  for (const LipStep& step : steps) {
    const double end = cone.highest - shifted;  // the wide end's height now
    // First: the part past the crease turned back over the sheet (seeded past the wide end).
    ring.planes.push_back({c + step.crease * d, d});
    ring.seeds.push_back(c + (end + rim) * d);
    // Then forward again past the second crease: the part on that side holding the turned-back
    // wide end (its rim, now at 2 crease - end, the farthest paper from the axis there), not the
    // sheet's narrow part, which lies on that side too.
    const double back = step.crease - step.width;
    ring.planes.push_back({c + back * d, -d});
    ring.seeds.push_back(c + (2.0 * step.crease - end) * d + 3.0 * rim * across);
    shifted += 2.0 * step.width;
  }
  return ring;
}

std::vector<FoldSuggestion> suggestLipPleats(const FoldSession& session, const FoldFitter& fitter,
                                             const RevolutionAxis& axis,
                                             const std::vector<SurfaceSample>& targetSamples,
                                             const Deadline& deadline) {
  if (session.symmetricFolder() || deadline.givesUp()) return {};
  const std::optional<ConeProfile> cone = coneProfile(session.fixed(), axis.direction);
  if (!cone) return {};
  const std::vector<std::vector<LipStep>> staircases = lipStaircases(*cone, targetSamples);
  if (staircases.empty()) return {};
  std::vector<Ring> rings;
  for (const std::vector<LipStep>& steps : staircases) rings.push_back(lipPleatRing(*cone, steps));
  const std::optional<std::vector<double>> scores =
      floorMeasuresOf(session, fitter, rings, deadline);
  if (!scores) return {};
  const double measuredBefore = floorMeasure(session.fixed(), fitter);
  const auto best = std::min_element(scores->begin(), scores->end());
  if (!(*best < measuredBefore)) return {};
  FoldSession grown(session.initial());
  const std::size_t base = session.foldCount();
  grown.applyRecords(std::vector<FoldRecord>(
      session.folds().begin(), session.folds().begin() + static_cast<std::ptrdiff_t>(base)));
  makeRing(grown, rings[static_cast<std::size_t>(best - scores->begin())]);
  FoldSuggestion suggestion;
  suggestion.folds.assign(grown.folds().begin() + static_cast<std::ptrdiff_t>(base),
                          grown.folds().begin() + static_cast<std::ptrdiff_t>(grown.foldCount()));
  suggestion.sheet = grown.fixed();
  suggestion.before = fitter.approximateDistance(session.fixed());
  suggestion.after = std::min(fitter.approximateDistance(suggestion.sheet),
                              suggestion.before * *best / measuredBefore);
  return {std::move(suggestion)};
}

}  // namespace curvefold
