#include "engine/fit/floor_rings.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include "engine/fit/ring_folds.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/self_intersection.hpp"

namespace curvefold {

namespace {

constexpr double kFacingAlong = 0.866;  // 30 degrees
constexpr double kFewestFloorSamples = 0.04;
constexpr double kShortestBand = 0.1;  // of the heel's radius
// The heel's radius: the sheet's vertices within this much of the heel's radius along the axis.
constexpr double kHeelSlab = 0.15;
constexpr int kOrders[] = {4, 5, 6, 8};
constexpr double kTiltsDegrees[] = {35.0, 45.0, 55.0};
constexpr double kGaps[] = {0.01, 0.03};  // of the heel's radius
constexpr std::size_t kMeasureSamples = 1500;

glm::dvec3 perpendicularTo(const glm::dvec3& a) {
  const glm::dvec3 other = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(other, a));
}

}  // namespace

std::optional<TargetFloor> targetFloor(const std::vector<SurfaceSample>& samples,
                                       const glm::dvec3& point, const glm::dvec3& direction) {
  if (samples.empty()) return std::nullopt;
  for (const double sign : {1.0, -1.0}) {
    const glm::dvec3 toward = sign * direction;
    double mean = 0.0;
    for (const SurfaceSample& s : samples) mean += glm::dot(s.position - point, toward);
    mean /= static_cast<double>(samples.size());
    // Facing along the axis past the samples' mean height: a floor at this end (a shoulder's
    // level ring or the other end's cap lie before it).
    double facing = 0.0, facingHeight = 0.0;
    for (const SurfaceSample& s : samples) {
      const double t = glm::dot(s.position - point, toward);
      if (t > mean && std::abs(glm::dot(s.normal, toward)) >= kFacingAlong) {
        facing += 1.0;
        facingHeight += t;
      }
    }
    if (facing < kFewestFloorSamples * static_cast<double>(samples.size())) continue;
    return TargetFloor{toward, facingHeight / facing};
  }
  return std::nullopt;
}

Ring floorRingOf(const FloorRingShape& shape, const glm::dvec3& point, const glm::dvec3& toward,
                 double height, double radius) {
  const glm::dvec3 u = perpendicularTo(toward), v = glm::cross(toward, u);
  const double chord = radius * std::cos(std::numbers::pi / shape.order);
  Ring ring;
  for (int k = 0; k < shape.order; ++k) {
    const double angle = shape.turn + 2.0 * std::numbers::pi * k / shape.order;
    const glm::dvec3 e = std::cos(angle) * u + std::sin(angle) * v;
    // Plane k a gap k nearer the rim: its flap lies a layer inside the one before.
    ring.planes.push_back(
        {point + (height - shape.gap * k) * toward + chord * e,
         glm::normalize(std::cos(shape.tilt) * e + std::sin(shape.tilt) * toward)});
  }
  return ring;
}

std::vector<FloorRingShape> floorRingShapes(const std::vector<glm::dvec3>& positions,
                                            const glm::dvec3& point, const TargetFloor& floor,
                                            double& radius) {
  double reach = -1e300, sum = 0.0, heelSpan = 0.0;
  std::size_t near = 0;
  // The heel's radius: the mean distance from the axis of the vertices about the floor's height
  // (widened until some lie there).
  for (const double slab : {kHeelSlab, 2.0 * kHeelSlab, 4.0 * kHeelSlab}) {
    sum = 0.0;
    near = 0;
    double widest = 0.0;
    for (const glm::dvec3& p : positions) {
      const double t = glm::dot(p - point, floor.toward);
      widest = std::max(widest, glm::length(p - point - t * floor.toward));
    }
    heelSpan = slab * widest;
    for (const glm::dvec3& p : positions) {
      const double t = glm::dot(p - point, floor.toward);
      reach = std::max(reach, t);
      if (std::abs(t - floor.height) <= heelSpan) {
        sum += glm::length(p - point - t * floor.toward);
        ++near;
      }
    }
    if (near >= 8) break;
  }
  if (near == 0) return {};
  radius = sum / static_cast<double>(near);
  if (!(radius > 0.0) || reach - floor.height < kShortestBand * radius) return {};
  std::vector<FloorRingShape> shapes;
  for (const int order : kOrders)
    for (const double tilt : kTiltsDegrees)
      for (const double gap : kGaps)
        shapes.push_back({order, tilt * std::numbers::pi / 180.0, gap * radius, 0.0});
  return shapes;
}

double floorMeasure(const Sheet& sheet, const FoldFitter& fitter) {
  const SurfaceDistance d =
      surfaceDistance(meshOf(sheet), fitter.measuredTarget(), kMeasureSamples);
  return d.chamfer + kTubeHausdorffWeight * d.hausdorff;
}

std::optional<FloorRing> bestFloorRing(const FoldSession& session, const FoldFitter& fitter,
                                       const RevolutionAxis& axis,
                                       const std::vector<SurfaceSample>& targetSamples,
                                       double current, const Deadline& deadline) {
  if (deadline.givesUp()) return std::nullopt;
  const std::optional<TargetFloor> floor = targetFloor(targetSamples, axis.point, axis.direction);
  if (!floor) return std::nullopt;
  double heel = 0.0;
  const std::vector<FloorRingShape> shapes =
      floorRingShapes(session.fixed().positions, axis.point, *floor, heel);
  if (shapes.empty()) return std::nullopt;
  std::vector<Ring> rings;
  for (const FloorRingShape& shape : shapes)
    rings.push_back(floorRingOf(shape, axis.point, floor->toward, floor->height, heel));
  const std::optional<std::vector<double>> scores =
      floorMeasuresOf(session, fitter, rings, deadline);
  if (!scores) return std::nullopt;
  const auto best = std::min_element(scores->begin(), scores->end());
  if (!(*best < current)) return std::nullopt;
  return FloorRing{rings[static_cast<std::size_t>(best - scores->begin())], *best};
}

std::optional<std::vector<double>> floorMeasuresOf(const FoldSession& session,
                                                   const FoldFitter& fitter,
                                                   const std::vector<Ring>& rings,
                                                   const Deadline& deadline) {
  const bool allowCrossing = fitter.settings().allowSelfIntersection;
  const std::size_t crossingsBefore =
      allowCrossing ? 0 : findSelfIntersections(session.fixed()).intersections.size();
  std::vector<double> scores(rings.size(), 1e300);
  RingTrials trials(session, allowCrossing ? std::nullopt : std::optional(crossingsBefore));
  tbb::parallel_for(std::size_t{0}, rings.size(), [&](std::size_t r) {
    if (deadline.passed()) return;
    deadline.countEvaluation();
    trials.tryRing(rings[r], rings[r].planes.size(), [&](const FoldSession& copy) {
      scores[r] = floorMeasure(copy.fixed(), fitter);
    });
  });
  if (deadline.passed()) return std::nullopt;
  return scores;
}

std::vector<FoldSuggestion> suggestFloorRing(const FoldSession& session, const FoldFitter& fitter,
                                             const RevolutionAxis& axis,
                                             const std::vector<SurfaceSample>& targetSamples,
                                             const Deadline& deadline,
                                             const FoldSuggestion* first) {
  if (session.symmetricFolder() || deadline.givesUp()) return {};
  const std::size_t base = session.foldCount();
  std::vector<FoldRecord> records(session.folds().begin(),
                                  session.folds().begin() + static_cast<std::ptrdiff_t>(base));
  if (first) records.insert(records.end(), first->folds.begin(), first->folds.end());
  FoldSession grown(session.initial());
  grown.applyRecords(records);
  const double measuredBefore = floorMeasure(grown.fixed(), fitter);
  const std::optional<FloorRing> floor =
      bestFloorRing(grown, fitter, axis, targetSamples, measuredBefore, deadline);
  if (!floor) return {};
  makeRing(grown, floor->ring);
  FoldSuggestion suggestion;
  suggestion.folds.assign(grown.folds().begin() + static_cast<std::ptrdiff_t>(base),
                          grown.folds().begin() + static_cast<std::ptrdiff_t>(grown.foldCount()));
  suggestion.sheet = grown.fixed();
  suggestion.before = first ? first->before : fitter.approximateDistance(session.fixed());
  const double from = first ? first->after : suggestion.before;
  suggestion.after = std::min(fitter.approximateDistance(suggestion.sheet),
                              from * floor->measured / measuredBefore);
  return {std::move(suggestion)};
}

}  // namespace curvefold
