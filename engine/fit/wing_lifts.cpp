#include "engine/fit/wing_lifts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/fit/pleat_folds.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/nearest_vertex.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/vertex_normals.hpp"

namespace curvefold {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// A target vertex this far from the sheet (of the target's diagonal) may be a wing's.
constexpr double kFar = 0.03;
// Target vertices measured, wings lifted (at least this far apart, of the sheet's size).
constexpr std::size_t kMeasured = 1500;
constexpr std::size_t kWings = 6;
constexpr double kWingApart = 0.25;
// Hinges at these shares of the far point's reach from the sheet's centre (and where the far
// point and the wing lie as far from the hinge, when that falls between the two).
constexpr double kReaches[] = {0.35, 0.65};
// The turn that carries the sheet's point onto the wing, and a share of it (the end beyond the
// point turns too, and may stand out past the wing).
constexpr double kTurnShares[] = {1.0, 0.7};
constexpr double kMostTurn = 75.0 * kDegree;
// A pleat's width (of the diagonal) and its flap's margin over the turn, as pleat_folds.cpp's.
constexpr double kWidth = 0.003;
constexpr double kFlapMargin = 4.0 * kDegree;
// Samples a side of each measure of a lift.
constexpr std::size_t kSamples = 3000;
// A lift is kept where its wing's far points come this much nearer, the Chamfer distance rising
// by this share at most.
constexpr double kWingNearer = 0.8;
constexpr double kChamferSlack = 0.02;

using Folds = std::vector<std::pair<ReflectionPlane, VertexIndex>>;

struct Lift {
  Folds folds;
  FoldSuggestion made;
  double wing = 0.0;  // the wing's far points' largest distance to the sheet after it
  double chamfer = 0.0;
};

}  // namespace

std::vector<FoldSuggestion> suggestWingLifts(FoldSession& session, const FoldFitter& fitter,
                                             std::size_t count, const Deadline& deadline) {
  session.cancel();
  std::vector<FoldSuggestion> out;
  if (count == 0 || session.symmetricFolder() || deadline.passed()) return out;
  const Sheet sheet = session.fixed();
  const std::size_t n = sheet.vertexCount();
  if (n < 4) return out;
  const std::vector<glm::dvec3> normals = vertexNormals(sheet);
  glm::dvec3 centre(0.0), lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : sheet.positions) {
    centre += p;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  centre /= static_cast<double>(n);
  const double size = glm::length(hi - lo);
  const MeasuredSurface& target = fitter.measuredTarget();
  const double diagonal = fitter.targetDiagonal();

  // The target's vertices far from the sheet, the farthest few apart: the wings.
  const std::vector<glm::dvec3>& vertices = target.usedVertices();
  const std::size_t stride = std::max<std::size_t>(1, vertices.size() / kMeasured);
  std::vector<glm::dvec3> points;
  for (std::size_t v = 0; v < vertices.size(); v += stride) points.push_back(vertices[v]);
  const SurfaceDistanceQuery sheetQuery(meshOf(sheet), "sheet");
  const std::vector<double> distances = pointDistances(points, sheetQuery);
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (distances[i] > kFar * diagonal) order.push_back(i);
  if (order.empty()) return out;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return distances[a] > distances[b]; });
  struct Wing {
    glm::dvec3 q{0.0};
    std::vector<glm::dvec3> far;  // its far target points (within kWingApart of q)
    double before = 0.0;          // their largest distance to the sheet
  };
  std::vector<Wing> wings;
  for (const std::size_t i : order) {
    if (wings.size() == kWings) break;
    if (std::all_of(wings.begin(), wings.end(), [&](const Wing& w) {
          return glm::distance(w.q, points[i]) > kWingApart * size;
        }))
      wings.push_back({points[i], {}, distances[i]});
  }
  for (const std::size_t i : order) {
    Wing* nearest = nullptr;
    for (Wing& w : wings)
      if (glm::distance(w.q, points[i]) <= kWingApart * size &&
          (!nearest || glm::distance(w.q, points[i]) < glm::distance(nearest->q, points[i])))
        nearest = &w;
    if (nearest) nearest->far.push_back(points[i]);
  }

  const SurfaceDistance before = surfaceDistance(meshOf(sheet), target, kSamples);
  const std::size_t crossingsBefore = findSelfIntersections(sheet).intersections.size();
  const std::size_t foldsBefore = session.foldCount();
  std::uint32_t group = 1;
  for (std::size_t f = 0; f < foldsBefore; ++f)
    group = std::max(group, session.folds()[f].group + 1);
  auto undoAll = [&] { session.undoTo(foldsBefore); };
  auto make = [&](const Folds& folds) {
    for (const auto& [plane, seed] : folds) {
      const glm::dvec3 grab = session.beginDragAtDevelopment(sheet.development[seed]);
      session.updateDrag(plane.reflect(grab));
      if (!session.commit()) return false;
    }
    return true;
  };
  // The folds made and measured: the sheet they leave (none where a fold is refused or they
  // cross the sheet more than before), with the distances of `far` to it; taken back.
  struct Measured {
    FoldSuggestion made;
    SurfaceDistance distance;
    double wing = 0.0;
  };
  auto measure = [&](const Folds& folds,
                     const std::vector<glm::dvec3>& far) -> std::optional<Measured> {
    deadline.countEvaluation();
    std::optional<Measured> result;
    if (make(folds) &&
        findSelfIntersections(session.fixed()).intersections.size() <= crossingsBefore) {
      result.emplace();
      result->made.folds.assign(
          session.folds().begin() + static_cast<std::ptrdiff_t>(foldsBefore),
          session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount()));
      for (FoldRecord& fold : result->made.folds) fold.group = group;  // one step
      result->made.sheet = session.fixed();
      const TriangleMesh mesh = meshOf(result->made.sheet);
      result->distance = surfaceDistance(mesh, target, kSamples);
      result->made.before = before.hausdorff;
      result->made.after = result->distance.hausdorff;
      if (!far.empty()) {
        const SurfaceDistanceQuery query(mesh, "sheet");
        for (const double d : pointDistances(far, query)) result->wing = std::max(result->wing, d);
      }
    }
    undoAll();
    return result;
  };

  // Each wing's lifts: hinges back from the sheet's point nearest it, turning the end toward it.
  const double width = kWidth * diagonal;
  std::vector<Lift> best;
  for (const Wing& wing : wings) {
    if (deadline.passed()) break;
    const glm::dvec3 p = sheetQuery.closestPoint(wing.q);
    const auto seed = static_cast<VertexIndex>(nearestVertex(sheet.positions, p));
    const glm::dvec3 m = normals[seed];
    if (!(glm::length(m) > 0.5)) continue;
    glm::dvec3 u = p - centre;
    u -= glm::dot(u, m) * m;
    const double reach = glm::length(u);
    if (!(reach > 0.05 * size)) continue;
    u /= reach;
    std::vector<double> backs;
    for (const double share : kReaches) backs.push_back(share * reach);
    // Where p and q lie as far from the hinge: |q - p + L u| = L.
    const glm::dvec3 pq = wing.q - p;
    if (const double along = glm::dot(u, pq); along < 0.0) {
      const double equal = -glm::dot(pq, pq) / (2.0 * along);
      if (equal > 0.2 * reach && equal < 0.9 * reach) backs.push_back(equal);
    }
    std::optional<Lift> kept;
    for (const double back : backs) {
      if (deadline.passed()) break;
      const auto at = static_cast<VertexIndex>(nearestVertex(sheet.positions, p - back * u));
      const glm::dvec3 h = sheet.positions[at], mh = normals[at];
      glm::dvec3 along = u - glm::dot(u, mh) * mh;
      if (!(glm::length(along) > 1e-6) || !(glm::length(mh) > 0.5)) continue;
      along = glm::normalize(along);
      if (!(glm::dot(sheet.positions[seed] - h, along) > 8.0 * width)) continue;
      // The turn about the hinge's line (along x mh) that carries p onto q's side of it.
      const glm::dvec3 axis = glm::normalize(glm::cross(mh, along));
      glm::dvec3 r = p - h, s = wing.q - h;
      r -= glm::dot(r, axis) * axis;
      s -= glm::dot(s, axis) * axis;
      const double phi = std::atan2(glm::dot(glm::cross(r, s), axis), glm::dot(r, s));
      // Turning along about `axis` by phi > 0 moves it toward -mh.
      const glm::dvec3 toward = phi > 0.0 ? -mh : mh;
      // How far the sheet rises and falls along the hinge: the pleat's planes pass at mid-height
      // and it is widened so it is nowhere narrower than `width` (as pleat_folds.cpp's).
      double low = 0.0, high = 0.0;
      for (std::size_t v = 0; v < n; ++v)
        if (std::abs(glm::dot(sheet.positions[v] - h, along)) < 0.02 * size) {
          const double height = glm::dot(sheet.positions[v] - h, mh);
          low = std::min(low, height);
          high = std::max(high, height);
        }
      for (const double share : kTurnShares) {
        const double theta = std::min(kMostTurn, share * std::abs(phi));
        if (!(theta > 2.0 * kDegree)) continue;
        const double wide = width + 0.6 * (high - low) * std::tan(0.5 * theta);
        const PleatPlanes pleat = pleatPlanes(h + 0.5 * (low + high) * mh, along, toward, theta,
                                              0.5 * theta + 0.5 * kFlapMargin, wide);
        // One fold: the plane through the hinge at half the turn out of the sheet's tangent.
        const ReflectionPlane single{
            h, -std::sin(0.5 * theta) * along + std::cos(0.5 * theta) * toward};
        for (const Folds& folds :
             {Folds{{single, seed}}, Folds{{pleat.first, seed}, {pleat.second, seed}}}) {
          if (deadline.passed()) break;
          std::optional<Measured> made = measure(folds, wing.far);
          if (!made || !(made->wing < kWingNearer * wing.before) ||
              made->distance.fromAMax > before.hausdorff ||
              made->distance.chamfer > (1.0 + kChamferSlack) * before.chamfer)
            continue;
          // Ranked by the farther of the wing's far points and the sheet's own farthest point:
          // the nearest wing alone takes a wide cap, which overlaps the next wing's.
          const double left = std::max(made->wing, made->distance.fromAMax);
          if (!kept || left < kept->wing)
            kept = Lift{folds, std::move(made->made), left, made->distance.chamfer};
        }
      }
    }
    if (kept) best.push_back(std::move(*kept));
  }
  if (best.empty()) return out;

  // Every wing's lift as one step, grown greedily (the farthest wing's first): a wing lifted
  // alone leaves the Hausdorff distance at the next one's.
  std::vector<FoldSuggestion> ranked;
  if (best.size() > 1 && !deadline.passed()) {
    Folds all = best.front().folds;
    std::optional<Measured> grown;
    for (std::size_t i = 1; i < best.size() && !deadline.passed(); ++i) {
      Folds more = all;
      more.insert(more.end(), best[i].folds.begin(), best[i].folds.end());
      std::optional<Measured> made = measure(more, {});
      if (made && made->distance.chamfer <= (1.0 + kChamferSlack) * before.chamfer &&
          (!grown || made->distance.hausdorff < grown->distance.hausdorff)) {
        all = std::move(more);
        grown = std::move(made);
      }
    }
    if (grown) ranked.push_back(std::move(grown->made));
  }
  for (Lift& lift : best) ranked.push_back(std::move(lift.made));
  std::stable_sort(
      ranked.begin(), ranked.end(),
      [](const FoldSuggestion& a, const FoldSuggestion& b) { return a.after < b.after; });
  if (ranked.size() > count) ranked.resize(count);
  return ranked;
}

}  // namespace curvefold
