#include "engine/fit/tuck_folds.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <span>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/nearest_vertex.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/vertex_normals.hpp"

namespace curvefold {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// A vertex this far from the target (of its diagonal) may stand past its rim.
constexpr double kFar = 0.02;
// Its way to the target runs along the sheet: under this cosine with the sheet's normal.
constexpr double kAlongSheet = 0.6;
// Vertices measured, far points tucked (at least this far apart, of the sheet's size).
constexpr std::size_t kMeasured = 1500;
constexpr std::size_t kFarPoints = 6;
constexpr double kFarApart = 0.25;
// The hinge's distance back from the far point, in units of how far it stands out.
constexpr double kDepths[] = {0.8, 1.0, 1.25};
// Where none of those is kept (its flap crossed the sheet, or stood out as far), the far point is
// tried again with hinges nearer and farther back and a steeper tilt: a corner left standing out
// is the sheet's Hausdorff point, so every one that stands out is worth the dearer try.
constexpr double kMoreDepths[] = {0.6, 1.6, 2.0};
// The tilt eps of the plane out of the sheet's normal plane (the flap lies at 2 eps).
constexpr double kTilts[] = {3.0 * kDegree, 7.0 * kDegree};
constexpr double kMoreTilts[] = {3.0 * kDegree, 7.0 * kDegree, 12.0 * kDegree};
// Where none of those is kept either, the hinge turned about the sheet's normal by these angles:
// a hinge across the outward way can cross a narrow pleat beside the corner, and a flap folded
// flat over a pleat cuts through itself (the judge's saddle20: two of four corners left standing,
// the pleats of its ends 2 cm inside them); turned, it runs beside the pleat instead.
constexpr double kTurns[] = {25.0 * kDegree, -25.0 * kDegree, 45.0 * kDegree, -45.0 * kDegree};
// A tuck is kept where the sheet stands out (excess) by this share of before at most, and the
// search's score (approximateDistance, which cuts far distances) rises by no more than this.
constexpr double kLessExcess = 0.9;
constexpr double kScoreSlack = 0.03;

// A step of tucks made, and how far the sheet then stands out (see excess).
struct Made : FoldSuggestion {
  double excess = 0.0;
};

struct Tuck {
  ReflectionPlane plane;
  VertexIndex seed = 0;  // a vertex of the flap, where the fold grabs it
  double after = 0.0;
};

}  // namespace

std::vector<FoldSuggestion> suggestTucks(FoldSession& session, const FoldFitter& fitter,
                                         std::size_t count, const Deadline& deadline, bool dearer) {
  session.cancel();
  std::vector<FoldSuggestion> out;
  if (count == 0 || session.symmetricFolder() || deadline.passed()) return out;
  const Sheet sheet = session.fixed();
  const std::size_t n = sheet.vertexCount();
  if (n < 4) return out;
  const std::vector<glm::dvec3> normals = vertexNormals(sheet);
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : sheet.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double size = glm::length(hi - lo);

  // Where the sheet stands past the target's rim: far, its way to the target along the sheet.
  const SurfaceDistanceQuery& query = fitter.measuredTarget().query();  // indexed once a fit
  const std::size_t stride = std::max<std::size_t>(1, n / kMeasured);
  std::vector<VertexIndex> measured;
  std::vector<glm::dvec3> points;
  for (std::size_t v = 0; v < n; v += stride) {
    measured.push_back(static_cast<VertexIndex>(v));
    points.push_back(sheet.positions[v]);
  }
  const std::vector<double> distances = pointDistances(points, query);
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < measured.size(); ++i)
    if (distances[i] > kFar * fitter.targetDiagonal()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return distances[a] > distances[b]; });
  struct Far {
    VertexIndex vertex = 0;
    double distance = 0.0;
    glm::dvec3 outward{0.0};  // away from the target, along the sheet
  };
  std::vector<Far> far;
  for (const std::size_t i : order) {
    if (far.size() == kFarPoints) break;
    const glm::dvec3 p = points[i];
    const glm::dvec3 m = normals[measured[i]];
    const glm::dvec3 away = (p - query.closestPoint(p)) / distances[i];
    if (!(glm::length(m) > 0.5) || std::abs(glm::dot(away, m)) > kAlongSheet) continue;
    if (std::any_of(far.begin(), far.end(), [&](const Far& f) {
          return glm::distance(sheet.positions[f.vertex], p) < kFarApart * size;
        }))
      continue;
    far.push_back({measured[i], distances[i], glm::normalize(away - glm::dot(away, m) * m)});
  }
  if (far.empty()) return out;

  const double before = fitter.approximateDistance(sheet);
  // How far the sheet stands out: the squares of its vertices' distances past kFar.
  const double far2 = kFar * fitter.targetDiagonal();
  // The sheet's own vertices measured once: a tuck moves its flap alone, and a vertex it leaves
  // where it was (bit for bit) keeps its distance, the query being a function of the point alone;
  // only the moved and the new vertices are measured again (measuring every vertex of every tuck
  // tried was half the CPU of a steep hypar's start choice under ASan).
  const std::vector<double> distancesBefore = pointDistances(sheet.positions, query);
  auto excess = [&](const Sheet& s) {
    std::vector<double> d(s.positions.size());
    std::vector<std::size_t> moved;
    std::vector<glm::dvec3> movedPoints;
    for (std::size_t v = 0; v < s.positions.size(); ++v)
      if (v < n && std::memcmp(&s.positions[v], &sheet.positions[v], sizeof(glm::dvec3)) == 0) {
        d[v] = distancesBefore[v];
      } else {
        moved.push_back(v);
        movedPoints.push_back(s.positions[v]);
      }
    const std::vector<double> measuredAgain = pointDistances(movedPoints, query);
    for (std::size_t i = 0; i < moved.size(); ++i) d[moved[i]] = measuredAgain[i];
    double sum = 0.0;
    for (const double x : d)
      if (x > far2) sum += (x - far2) * (x - far2);
    return sum;
  };
  const double excessBefore = excess(sheet);
  const std::size_t crossingsBefore = findSelfIntersections(sheet).intersections.size();
  const std::size_t foldsBefore = session.foldCount();
  std::uint32_t group = 1;
  for (std::size_t f = 0; f < foldsBefore; ++f)
    group = std::max(group, session.folds()[f].group + 1);
  auto undoAll = [&] { session.undoTo(foldsBefore); };
  // The tucks made, in turn; false where the session refuses one (a sliver).
  auto make = [&](const std::vector<Tuck>& tucks) {
    for (const Tuck& tuck : tucks) {
      const glm::dvec3 grab = session.beginDragAtDevelopment(sheet.development[tuck.seed]);
      if (!(tuck.plane.signedDistance(grab) > 0.0)) {
        session.cancel();
        return false;
      }
      session.updateDrag(tuck.plane.reflect(grab));
      if (!session.commit()) return false;
    }
    return true;
  };
  // The tucks made and scored (none where they cross the sheet more than before), taken back.
  auto score = [&](const std::vector<Tuck>& tucks) -> std::optional<Made> {
    deadline.countEvaluation();
    std::optional<Made> made;
    if (make(tucks)) {
      const double after = fitter.approximateDistance(session.fixed());
      // The cheaper tests first: the excess only of a tuck the search's score keeps.
      double excessAfter = 0.0;
      if (after <= (1.0 + kScoreSlack) * before &&
          (excessAfter = excess(session.fixed())) < kLessExcess * excessBefore &&
          findSelfIntersections(session.fixed()).intersections.size() <= crossingsBefore) {
        made.emplace();
        made->folds.assign(
            session.folds().begin() + static_cast<std::ptrdiff_t>(foldsBefore),
            session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount()));
        // One group: undo takes the tucks at once, and a fit counts them as one step.
        for (FoldRecord& fold : made->folds) fold.group = group;
        made->sheet = session.fixed();
        made->before = before;
        made->after = after;
        made->excess = excessAfter;
      }
    }
    undoAll();
    return made;
  };

  // Each far point's best tuck: the usual hinges, then (none kept) the dearer ones.
  std::vector<std::pair<Tuck, Made>> best;
  auto tryHinges = [&](const Far& f, std::span<const double> depths, std::span<const double> tilts,
                       double turn = 0.0) {
    std::optional<std::pair<Tuck, Made>> kept;
    const glm::dvec3 p = sheet.positions[f.vertex];
    // The outward way turned about the sheet's normal at the far point by `turn`.
    const glm::dvec3 pm = normals[f.vertex];
    const glm::dvec3 outward =
        std::cos(turn) * f.outward + std::sin(turn) * glm::cross(pm, f.outward);
    for (const double depth : depths) {
      if (deadline.passed()) break;
      // The hinge: the sheet's vertex nearest the point that far back, and the sheet's tangent
      // there along the outward way.
      const glm::dvec3 wanted = p - depth * f.distance * outward;
      const auto at = static_cast<VertexIndex>(nearestVertex(sheet.positions, wanted));
      const glm::dvec3 h = sheet.positions[at], m = normals[at];
      glm::dvec3 along = outward - glm::dot(outward, m) * m;
      if (!(glm::length(along) > 1e-6) || !(glm::length(m) > 0.5)) continue;
      along = glm::normalize(along);
      if (!(glm::dot(p - h, along) > 0.0)) continue;
      for (const double tilt : tilts)
        for (const double side : {1.0, -1.0}) {
          Tuck tuck{{h, std::cos(tilt) * along + side * std::sin(tilt) * m}, f.vertex, 0.0};
          if (std::optional<Made> made = score({tuck})) {
            tuck.after = made->excess;
            if (!kept || tuck.after < kept->first.after) kept.emplace(tuck, std::move(*made));
          }
        }
    }
    return kept;
  };
  for (const Far& f : far) {
    std::optional<std::pair<Tuck, Made>> kept = tryHinges(f, kDepths, kTilts);
    if (!kept && dearer) kept = tryHinges(f, kMoreDepths, kMoreTilts);
    for (const double turn : kTurns) {
      if (kept || !dearer || deadline.passed()) break;
      kept = tryHinges(f, kDepths, kTilts, turn);
    }
    if (kept) best.push_back(std::move(*kept));
  }
  if (best.empty()) return out;
  std::vector<Made> ranked;
  // Every far point's tuck as one step, then the single tucks.
  // Where all of them together are refused (two flaps crossing each other: a grown square's
  // corner and the middle of a side beside it), a group grown greedily instead, the farthest
  // point's tuck first, each next one kept where the group with it still scores.
  if (best.size() > 1 && !deadline.passed()) {
    std::vector<Tuck> all;
    for (const auto& b : best) all.push_back(b.first);
    if (std::optional<Made> made = score(all)) {
      ranked.push_back(std::move(*made));
    } else {
      std::vector<Tuck> group{best.front().first};
      std::optional<Made> grown;
      for (std::size_t i = 1; i < best.size() && !deadline.passed(); ++i) {
        group.push_back(best[i].first);
        if (std::optional<Made> made = score(group))
          grown = std::move(made);
        else
          group.pop_back();
      }
      if (grown) ranked.push_back(std::move(*grown));
    }
  }
  for (auto& b : best) ranked.push_back(std::move(b.second));
  // Ranked by how far the sheet still stands out, not by the search's score, which cuts far
  // distances and barely sees a corner: ranked by it, the fit's rounds took a near corner's tuck
  // (Chamfer a little lower) before the farthest one's, one round each (an ellipse saddle from a
  // square: three rounds with Hausdorff unchanged at 14.2%, the clock's share spent before the
  // fourth).
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const Made& a, const Made& b) { return a.excess < b.excess; });
  if (ranked.size() > count) ranked.resize(count);
  for (Made& made : ranked) out.push_back(std::move(made));
  return out;
}

}  // namespace curvefold
