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

namespace {

// An orthonormal frame at positions[0] from two vertices far apart (the same indices in both
// sheets of a rigid pair): columns x, y, z.
struct Frame {
  glm::dvec3 origin, axes[3];
};
Frame frameOf(const std::vector<glm::dvec3>& positions, std::size_t i, std::size_t j) {
  Frame f;
  f.origin = positions[0];
  f.axes[0] = glm::normalize(positions[i] - f.origin);
  const glm::dvec3 w = positions[j] - f.origin;
  f.axes[1] = glm::normalize(w - glm::dot(w, f.axes[0]) * f.axes[0]);
  f.axes[2] = glm::cross(f.axes[0], f.axes[1]);
  return f;
}

}  // namespace

std::optional<ContinuedCone> continuedCone(const Sheet& cone, const SurfaceParameters& parameters,
                                           const std::vector<SurfaceSample>& samples,
                                           const RevolutionAxis& axis) {
  const auto base = parameters.find("base_radius"), top = parameters.find("top_radius"),
             tall = parameters.find("height");
  if (base == parameters.end() || top == parameters.end() || tall == parameters.end())
    return std::nullopt;
  const double r0 = base->second, r1 = top->second, h = tall->second;
  if (!(r1 > 0.0 && r0 > r1 && h > 0.0)) return std::nullopt;
  const std::optional<TargetFloor> floor = targetFloor(samples, axis.point, axis.direction);
  if (!floor) return std::nullopt;
  // The rigid motion that placed the catalogue cone: frames of the same three vertices.
  const Sheet catalogue = makeSurface("cone", parameters);
  if (catalogue.positions.size() != cone.positions.size() || cone.positions.size() < 3)
    return std::nullopt;
  std::size_t i = 1, j = 1;
  for (std::size_t k = 1; k < cone.positions.size(); ++k)
    if (glm::length(cone.positions[k] - cone.positions[0]) >
        glm::length(cone.positions[i] - cone.positions[0]))
      i = k;
  const glm::dvec3 along = glm::normalize(cone.positions[i] - cone.positions[0]);
  double off = -1.0;
  for (std::size_t k = 1; k < cone.positions.size(); ++k) {
    const glm::dvec3 w = cone.positions[k] - cone.positions[0];
    const double d = glm::length(w - glm::dot(w, along) * along);
    if (d > off) off = d, j = k;
  }
  if (!(off > 1e-9)) return std::nullopt;
  const Frame from = frameOf(catalogue.positions, i, j), to = frameOf(cone.positions, i, j);
  const auto moved = [&](const glm::dvec3& p) {
    const glm::dvec3 q = p - from.origin;
    return to.origin + glm::dot(q, from.axes[0]) * to.axes[0] +
           glm::dot(q, from.axes[1]) * to.axes[1] + glm::dot(q, from.axes[2]) * to.axes[2];
  };
  // The catalogue's cone stands along y, its base at -h / 2, its narrow end at +h / 2.
  const glm::dvec3 wide = moved(glm::dvec3(0.0, -0.5 * h, 0.0));
  const glm::dvec3 narrow = moved(glm::dvec3(0.0, 0.5 * h, 0.0));
  const glm::dvec3 direction = glm::normalize(narrow - wide);
  if (glm::dot(direction, floor->toward) < 0.9) return std::nullopt;  // its narrow end elsewhere
  const glm::dvec3 floorPoint = axis.point + floor->height * floor->toward;
  const double atFloor = glm::dot(floorPoint - wide, direction);  // along the cone from its base
  const double slope = (r0 - r1) / h;
  const double heel = r0 - slope * atFloor;
  if (!(heel > 0.0)) return std::nullopt;
  const double band = h - atFloor;  // past the floor now
  double extra = kContinuedBand * heel - band;
  extra = std::min(extra, (r1 - 0.2 * heel) / slope);
  if (!(extra > 0.1 * heel)) return std::nullopt;
  ContinuedCone out;
  out.parameters = parameters;
  out.parameters["top_radius"] = r1 - slope * extra;
  out.parameters["height"] = h + extra;
  out.sheet = makeSurface("cone", out.parameters);
  // Its base where the cone's was: the catalogue's longer cone moved by half the extra along y.
  for (glm::dvec3& p : out.sheet.positions) p = moved(p + glm::dvec3(0.0, 0.5 * extra, 0.0));
  return out;
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
  const bool allowCrossing = fitter.settings().allowSelfIntersection;
  const std::size_t crossingsBefore =
      allowCrossing ? 0 : findSelfIntersections(session.fixed()).intersections.size();
  std::vector<Ring> rings;
  for (const FloorRingShape& shape : shapes)
    rings.push_back(floorRingOf(shape, axis.point, floor->toward, floor->height, heel));
  std::vector<double> scores(rings.size(), 1e300);
  RingTrials trials(session, allowCrossing ? std::nullopt : std::optional(crossingsBefore));
  tbb::parallel_for(std::size_t{0}, rings.size(), [&](std::size_t r) {
    if (deadline.passed()) return;
    deadline.countEvaluation();
    trials.tryRing(rings[r], rings[r].planes.size(), [&](const FoldSession& copy) {
      scores[r] = floorMeasure(copy.fixed(), fitter);
    });
  });
  if (deadline.passed()) return std::nullopt;  // the scores are partial
  const auto best = std::min_element(scores.begin(), scores.end());
  if (!(*best < current)) return std::nullopt;
  return FloorRing{rings[static_cast<std::size_t>(best - scores.begin())], *best};
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
