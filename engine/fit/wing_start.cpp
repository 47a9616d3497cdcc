#include "engine/fit/wing_start.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {
namespace {

constexpr int kDirections = 16;
constexpr double kHinges[] = {0.2, 0.35, 0.5, 0.65};
constexpr double kLessTurn = 0.6;
constexpr std::size_t kMostWings = 6;
// Wings the height model ranks best, made and measured exactly each round.
constexpr std::size_t kMeasured = 24;
// The wedge of target samples a wing's turn is solved on: this half angle about its direction.
constexpr double kWedgeDegrees = 30.0;
// Turns steeper than this are left short (a fold near 90 degrees stands the flap on edge).
constexpr double kMostTurnDegrees = 75.0;
// A wing is kept where it lowers the score (Chamfer + kHausdorffWeight Hausdorff) by this share.
constexpr double kLeastGain = 0.02;
constexpr double kHausdorffWeight = 0.5;
constexpr std::size_t kTargetSamples = 3000;
constexpr std::size_t kMeasureSamples = 600;
constexpr std::size_t kLeastWedgeSamples = 12;

}  // namespace

std::optional<PlacedStart> wingStart(const PlacedStart& flat, const FoldFitter& fitter,
                                     const Deadline& deadline) {
  const Sheet& sheet = flat.sheet;
  if (sheet.positions.size() < 3 || sheet.triangles.empty()) return std::nullopt;
  // The sheet's plane: its area-weighted normal, every vertex on it.
  glm::dvec3 normal(0.0), centre(0.0), lo(1e300), hi(-1e300);
  for (const Triangle& t : sheet.triangles)
    normal += glm::cross(sheet.positions[t[1]] - sheet.positions[t[0]],
                         sheet.positions[t[2]] - sheet.positions[t[0]]);
  for (const glm::dvec3& p : sheet.positions) {
    centre += p;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double size = glm::length(hi - lo);
  if (!(glm::length(normal) > 0.0) || !(size > 0.0)) return std::nullopt;
  normal = glm::normalize(normal);
  centre /= static_cast<double>(sheet.positions.size());
  for (const glm::dvec3& p : sheet.positions)
    if (std::abs(glm::dot(p - centre, normal)) > 1e-6 * size) return std::nullopt;
  const glm::dvec3 helper =
      std::abs(normal.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(normal, helper)), e2 = glm::cross(normal, e1);

  const std::vector<SurfaceSample> samples = sampleSurface(fitter.target(), kTargetSamples, 7);
  auto measure = [&](const Sheet& s) {
    return surfaceDistance(meshOf(s), fitter.measuredTarget(), kMeasureSamples);
  };
  auto scoreOf = [](const SurfaceDistance& d) {
    return d.chamfer + kHausdorffWeight * d.hausdorff;
  };

  FoldSession session(sheet);
  const SurfaceDistance flatDistance = measure(sheet);
  double best = scoreOf(flatDistance);
  const double start = best;
  std::size_t crossings = findSelfIntersections(sheet).intersections.size();
  const double tanWedge = std::tan(kWedgeDegrees * M_PI / 180.0);
  const double mostTurn = kMostTurnDegrees * M_PI / 180.0;
  // The sheet's height over its plane under each target sample, as the wings kept so far lay it
  // (each wing's flap a ramp beyond its hinge, the latest over the earlier): the model that ranks
  // the wings to measure.
  std::vector<double> model(samples.size(), 0.0);
  std::size_t wings = 0;
  for (; wings < kMostWings && !deadline.passed(); ++wings) {
    const Sheet current = session.fixed();
    const std::size_t foldsBefore = session.foldCount();
    struct Wing {
      ReflectionPlane plane;
      glm::dvec2 seed{0.0};
      glm::dvec3 along{0.0};
      double hinge = 0.0, slope = 0.0, gain = 0.0;
      double score = 1e300;
    };
    std::vector<Wing> ranked, tried;
    for (int k = 0; k < kDirections && !deadline.passed(); ++k) {
      const double angle = 2.0 * M_PI * k / kDirections;
      const glm::dvec3 d = std::cos(angle) * e1 + std::sin(angle) * e2,
                       side = glm::cross(normal, d);
      // The sheet's reach that way, on the flat sheet (its development is the same).
      double reach = 0.0;
      for (const glm::dvec3& p : sheet.positions) reach = std::max(reach, glm::dot(p - centre, d));
      for (const double at : kHinges) {
        const double hinge = at * reach;
        // The target's height over the sheet's plane in the wedge beyond the hinge: the slope
        // through the hinge in least squares (the flap turns about it, height 0 there).
        double xx = 0.0, xh = 0.0, farthest = 0.0;
        std::size_t in = 0;
        for (const SurfaceSample& s : samples) {
          const glm::dvec3 r = s.position - centre;
          const double along = glm::dot(r, d), x = along - hinge;
          if (x <= 0.0 || std::abs(glm::dot(r, side)) > tanWedge * along) continue;
          xx += x * x;
          xh += x * glm::dot(r, normal);
          farthest = std::max(farthest, x);
          ++in;
        }
        if (in < kLeastWedgeSamples || !(xx > 0.0)) continue;
        // And the slope out to the wedge's far half alone (a wing that steepens toward its tip,
        // z ~ rho^3, is left short by the slope over all of it).
        double tipX = 0.0, tipH = 0.0;
        for (const SurfaceSample& s : samples) {
          const glm::dvec3 r = s.position - centre;
          const double along = glm::dot(r, d), x = along - hinge;
          if (x <= 0.5 * farthest || std::abs(glm::dot(r, side)) > tanWedge * along) continue;
          tipX += x;
          tipH += glm::dot(r, normal);
        }
        // And over the whole flap beyond the hinge (as wide as the sheet: a lobe's neighbours).
        double wideXX = 0.0, wideXH = 0.0;
        for (const SurfaceSample& s : samples) {
          const glm::dvec3 r = s.position - centre;
          const double x = glm::dot(r, d) - hinge;
          if (x <= 0.0) continue;
          wideXX += x * x;
          wideXH += x * glm::dot(r, normal);
        }
        const double slope = std::atan(xh / xx);
        const double turns[] = {slope, kLessTurn * slope, tipX > 0.0 ? std::atan(tipH / tipX) : 0.0,
                                std::atan(wideXH / wideXX)};
        // The seed: the flat sheet's vertex farthest beyond the hinge that no wing has moved (a
        // vertex keeps its index and development point through the folds).
        std::optional<glm::dvec2> seed;
        double far = hinge;
        for (std::size_t v = 0; v < sheet.positions.size(); ++v) {
          const double beyond = glm::dot(sheet.positions[v] - centre, d);
          if (beyond > far && v < current.positions.size() &&
              glm::distance(current.positions[v], sheet.positions[v]) < 1e-9 * size) {
            far = beyond;
            seed = sheet.development[v];
          }
        }
        if (!seed || far < hinge + 0.1 * reach) continue;
        for (const double solved : turns) {
          const double turn = std::clamp(solved, -mostTurn, mostTurn);
          if (std::abs(turn) < 0.02) continue;
          // The model's gain: squared height removed over the whole flap (its neighbours'
          // falling wings too, which a flap as wide as the sheet covers).
          const double t = std::tan(turn);
          double gain = 0.0;
          for (std::size_t i = 0; i < samples.size(); ++i) {
            const glm::dvec3 r = samples[i].position - centre;
            const double x = glm::dot(r, d) - hinge, h = glm::dot(r, normal);
            if (x > 0.0) gain += (h - model[i]) * (h - model[i]) - (h - x * t) * (h - x * t);
          }
          if (!(gain > 0.0)) continue;
          const glm::dvec3 turned = std::cos(turn) * d + std::sin(turn) * normal;
          ranked.push_back(
              {{centre + hinge * d, glm::normalize(d - turned)}, *seed, d, hinge, t, gain});
        }
      }
    }
    // The wings the model ranks best made on the sheet and measured exactly.
    std::sort(ranked.begin(), ranked.end(),
              [](const Wing& a, const Wing& b) { return a.gain > b.gain; });
    if (ranked.size() > kMeasured) ranked.resize(kMeasured);
    for (const Wing& wing : ranked) {
      if (deadline.passed()) break;
      deadline.countEvaluation();
      const glm::dvec3 grab = session.beginDragAtDevelopment(wing.seed);
      if (!(wing.plane.signedDistance(grab) > 0.0)) {
        session.cancel();
        continue;
      }
      session.updateDrag(wing.plane.reflect(grab));
      if (!session.commit()) continue;
      const SurfaceDistance landed = measure(session.fixed());
      Wing made = wing;
      made.score = scoreOf(landed);
      tried.push_back(made);
      session.undoTo(foldsBefore);
    }
    // The best that helps and crosses the sheet no more than before.
    std::sort(tried.begin(), tried.end(),
              [](const Wing& a, const Wing& b) { return a.score < b.score; });
    bool kept = false;
    for (const Wing& wing : tried) {
      if (!(wing.score < (1.0 - kLeastGain) * best)) break;
      const glm::dvec3 grab = session.beginDragAtDevelopment(wing.seed);
      session.updateDrag(wing.plane.reflect(grab));
      if (!session.commit()) continue;
      const std::size_t now = findSelfIntersections(session.fixed()).intersections.size();
      if (now <= crossings) {
        crossings = now;
        best = wing.score;
        kept = true;
        for (std::size_t i = 0; i < samples.size(); ++i) {
          const double x = glm::dot(samples[i].position - centre, wing.along) - wing.hinge;
          if (x > 0.0) model[i] = x * wing.slope;
        }
        break;
      }
      session.undoTo(foldsBefore);
    }
    if (!kept) break;
  }
  if (wings == 0) return std::nullopt;
  PlacedStart out{"winged_" + flat.surface, flat.parameters, "", session.fixed()};
  char text[160];
  std::snprintf(text, sizeof text,
                "%zu wing%s folded first (score %.4g -> %.4g, in the target's units); ", wings,
                wings == 1 ? "" : "s", start, best);
  out.placement = text + flat.placement;
  return out;
}

}  // namespace curvefold
