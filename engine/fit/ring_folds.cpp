#include "engine/fit/ring_folds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "engine/fit/eigen_glm.hpp"
#include "engine/fit/floor_rings.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/timed_batches.hpp"
#include "engine/geometry/principal_moments.hpp"
#include "engine/geometry/self_intersection.hpp"

namespace curvefold {
namespace {

// Sheet samples neckRings solves each ring on; a tube's radius spread allowed.
constexpr std::size_t kProfileSamples = 1200;
constexpr double kTubeSpread = 0.03;
// Samples a side of the distance rings made on the sheet are chosen by: the search's robust
// distance caps far points, and a tube's untouched neck is all far points.
constexpr std::size_t kMeasureSamples = 1500;
// Rings are chosen by Chamfer + kTubeHausdorffWeight times Hausdorff, so that a ring of 4 which
// comes closer on average but leaves a flap across the axis is not taken over finer rings (the
// example vase: 1.39% / 9.8% against 1.57% / 4.32%).
// The tube's axis and the target's are one direction (cosine of the angle between them).
constexpr double kSameDirection = 0.98;
// The orders of the two chains' rings: 6 to 16 (a ring of 6 cuts to 0.83 of the radius, 16 to
// 0.97), and 4 to 16 (4 cuts to 0.65, 5 to 0.76, a coarser star).
constexpr int kFineOrders[] = {6, 8, 12, 16};
constexpr int kAllOrders[] = {4, 5, 6, 8, 12, 16};
// A corner ring's planes at these fractions of its ring's distance from the axis.
constexpr double kCornerInward[] = {1.0, 0.95};
// Neck corner rings (neckCornerRing): height bins of the profile, how far toward the excess's
// peak a ring's cut may begin (where the excess falls below this share of the peak), and where
// between the target's radius and the corners' the planes pass at the peak (0.5: the corners
// fold onto the target's radius there).
constexpr int kCornerBins = 24;
constexpr double kCornerStart = 0.25;
constexpr double kCornerDepths[] = {0.5, 0.75};
// Where a neck pleat's cut begins: where the excess falls below this share of its peak.
constexpr double kPleatStart = 0.25;

// The profile of the sheet and the target about `axis` in kCornerBins height bins over the
// sheet's height: the sheet's largest radius in each, the target's mean (its sum and count),
// and the excess of the one over the other (-1e300 where either has fewer than 3 samples), with
// its peak and the sheet's largest radius over all. None for a sheet of no height.
struct ProfileBins {
  double lo = 0.0, hi = 0.0;
  std::array<double, kCornerBins> largest{}, targetSum{};
  std::array<int, kCornerBins> sheetCount{}, targetCount{};
  std::array<double, kCornerBins> excess{};
  double radius = 0.0;
  int peak = -1;
};

std::optional<ProfileBins> binProfile(const std::vector<SurfaceSample>& sheetSamples,
                                      const std::vector<SurfaceSample>& targetSamples,
                                      const RevolutionAxis& axis) {
  const auto heightAndRadius = [&](const glm::dvec3& p) {
    const double h = glm::dot(p - axis.point, axis.direction);
    return glm::dvec2(h, glm::length(p - axis.point - h * axis.direction));
  };
  ProfileBins out;
  double lo = 1e300, hi = -1e300;
  for (const SurfaceSample& s : sheetSamples) {
    const double h = heightAndRadius(s.position).x;
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  if (!(hi - lo > 1e-9)) return std::nullopt;
  out.lo = lo;
  out.hi = hi;
  const auto bin = [&](double h) { return static_cast<int>((h - lo) / (hi - lo) * kCornerBins); };
  for (const SurfaceSample& s : sheetSamples) {
    const glm::dvec2 hr = heightAndRadius(s.position);
    const int b = std::clamp(bin(hr.x), 0, kCornerBins - 1);
    out.largest[b] = std::max(out.largest[b], hr.y);
    ++out.sheetCount[b];
  }
  for (const SurfaceSample& s : targetSamples) {
    const glm::dvec2 hr = heightAndRadius(s.position);
    const int b = bin(hr.x);
    if (b < 0 || b >= kCornerBins) continue;
    out.targetSum[b] += hr.y;
    ++out.targetCount[b];
  }
  for (int b = 0; b < kCornerBins; ++b) {
    out.radius = std::max(out.radius, out.largest[b]);
    out.excess[b] = out.sheetCount[b] >= 3 && out.targetCount[b] >= 3
                        ? out.largest[b] - out.targetSum[b] / out.targetCount[b]
                        : -1e300;
    if (out.peak < 0 || out.excess[b] > out.excess[out.peak]) out.peak = b;
  }
  return out;
}

// A corner ring that folds in the corners standing farthest out of the target (a narrow neck's):
// the ring of `order` planes turned by `turn`, each plane through the corners' radius where the
// excess of the sheet's largest radius over the target's mean radius (by height) begins, and
// through `depth` of the way from the target's radius to the corners' at the excess's peak, so
// the cut deepens toward the peak and past it toward the end `side` (+1 the axis's end, -1 the
// other) rather than growing linearly from an end as neckRings' rings do. None where no bin
// stands out by a twentieth of the radius or the cut would begin at the peak.
std::optional<RingShape> neckCornerRing(const std::vector<SurfaceSample>& sheetSamples,
                                        const std::vector<SurfaceSample>& targetSamples,
                                        const RevolutionAxis& axis, int order, double turn,
                                        int side, double depth) {
  const std::optional<ProfileBins> bins = binProfile(sheetSamples, targetSamples, axis);
  if (!bins) return std::nullopt;
  // Named references, not a structured binding: the lambdas below capture them (clang 15).
  const double lo = bins->lo, hi = bins->hi, radius = bins->radius;
  const int peak = bins->peak;
  const auto &largest = bins->largest, &targetSum = bins->targetSum, &excess = bins->excess;
  const auto& targetCount = bins->targetCount;
  if (peak < 0 || !(excess[peak] > 0.05 * radius)) return std::nullopt;
  // The cut begins on the side away from `side`, where the excess falls off.
  int begin = peak;
  while (begin - side >= 0 && begin - side < kCornerBins &&
         excess[begin] > kCornerStart * excess[peak])
    begin -= side;
  if (begin == peak || excess[begin] < -1e299) return std::nullopt;
  const auto centre = [&](int b) { return lo + (hi - lo) * (b + 0.5) / kCornerBins; };
  const double t0 = centre(begin), tPeak = centre(peak), radius0 = largest[begin];
  const double rhoPeak = targetSum[peak] / targetCount[peak] + depth * excess[peak];
  const double g = (rhoPeak - radius0) / (tPeak - t0);
  RingShape shape;
  shape.height = t0;
  shape.radius = radius0;
  shape.tilt = std::atan(-g);
  shape.turn = turn;
  shape.order = order;
  return shape;
}

}  // namespace

// The profile binned (binProfile); the first ring's depth, then its flaps' middle at
// the neck and far end reflected in the meridian (see the header).
std::optional<std::array<RingShape, 2>> neckPleat(const std::vector<SurfaceSample>& sheetSamples,
                                                  const std::vector<SurfaceSample>& targetSamples,
                                                  const RevolutionAxis& axis, int order,
                                                  double turn, int side) {
  const std::optional<ProfileBins> bins = binProfile(sheetSamples, targetSamples, axis);
  if (!bins) return std::nullopt;
  // Named references, not a structured binding: the lambdas below capture them (clang 15).
  const double lo = bins->lo, hi = bins->hi, radius = bins->radius;
  const int peak = bins->peak;
  const auto &largest = bins->largest, &targetSum = bins->targetSum, &excess = bins->excess;
  const auto &sheetCount = bins->sheetCount, &targetCount = bins->targetCount;
  if (peak < 0 || !(excess[peak] > 0.05 * radius)) return std::nullopt;
  int begin = peak;
  while (begin - side >= 0 && begin - side < kCornerBins &&
         excess[begin] > kPleatStart * excess[peak])
    begin -= side;
  const int end = side > 0 ? kCornerBins - 1 : 0;
  if (begin == peak || end == peak || excess[begin] < -1e299 || sheetCount[end] < 3)
    return std::nullopt;
  const auto centre = [&](int b) { return lo + (hi - lo) * (b + 0.5) / kCornerBins; };
  const double t0 = centre(begin), tPeak = centre(peak), radius0 = largest[begin];
  const double wall = largest[peak], neck = targetSum[peak] / targetCount[peak];
  // The cut deepens on past the neck to the sheet's end: the wedges must stay apart there too,
  // at the rim (cos(pi / n)) and within (a flap's bulge stays in its own sector while q >=
  // 1 / (2 sin(pi / n)): a ring of 3 cut deeper crosses itself near the axis).
  const double apart =
      1.02 * std::max(std::cos(std::numbers::pi / order), 0.5 / std::sin(std::numbers::pi / order));
  const double rhoPeak = std::max(0.5 * (wall + neck), wall * apart);
  const double slope = std::min((radius0 - rhoPeak) / (tPeak - t0) * side,
                                (radius0 - largest[end] * apart) / (centre(end) - t0) * side);
  if (!(slope > 0.0)) return std::nullopt;
  RingShape in;
  in.height = t0;
  in.radius = radius0;
  in.tilt = std::atan(slope * side);
  in.turn = turn;
  in.order = order;
  // The wall at (r, t) in the meridian of a plane of `in`, reflected through it.
  const auto reflected = [&](double r, double t) {
    const double c = std::cos(in.tilt), s = std::sin(in.tilt);
    const double d = (r - in.radius) * c + (t - in.height) * s;
    return glm::dvec2(r - 2.0 * d * c, t - 2.0 * d * s);
  };
  const glm::dvec2 middle = reflected(wall, tPeak);
  const glm::dvec2 farEnd = reflected(largest[end], centre(end));
  if (!(farEnd.x < middle.x - 0.02 * radius)) return std::nullopt;
  // The return ring: its planes along -e_k (turned by half a turn) at the flap's middle.
  RingShape back;
  back.height = middle.y;
  back.radius = -middle.x;
  back.tilt = 0.0;
  back.turn = turn + std::numbers::pi;
  back.order = order;
  back.seeded = true;
  back.seedHeight = farEnd.y;
  back.seedRadius = -farEnd.x;
  return std::array<RingShape, 2>{in, back};
}

std::optional<TubeAxis> tubeAbout(const Sheet& sheet, const glm::dvec3& direction,
                                  double steepestTaper) {
  if (sheet.positions.size() < 4) return std::nullopt;
  // The middle of its bounding box: a tube's seam has its vertices twice, which pulls the
  // centroid toward it.
  glm::dvec3 low(1e300), high(-1e300);
  for (const glm::dvec3& p : sheet.positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const glm::dvec3 boxCentre = 0.5 * (low + high);
  // The tube's own axis: of the given direction and the vertices' principal axes, the one about
  // which the radius varies least (a start placed from other samples lies a little off the
  // target's axis, and a tube as long as it is wide has no distinct principal axis).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
      eigenOf(pointMoments(sheet.positions, {}, boxCentre).scatter));
  std::vector<glm::dvec3> candidates{glm::normalize(direction)};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = solver.eigenvectors().col(k);
    candidates.emplace_back(e.x(), e.y(), e.z());
  }
  std::optional<TubeAxis> best;
  double bestSpread = 1e300;
  for (const glm::dvec3& d : candidates) {
    if (std::abs(glm::dot(d, glm::normalize(direction))) < kSameDirection) continue;
    // The radius as a line of the height (a cylinder's slope 0, a cone's its taper), by least
    // squares; the spread is that of the radius about the line.
    // The axis point: the middle of the box across `d` (a tilted cone's box about the world's
    // axes is not centred on its axis; a box across its own axis is, turn by turn).
    const glm::dvec3 e1 = glm::normalize(
        glm::cross(std::abs(d.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0), d));
    const glm::dvec3 e2 = glm::cross(d, e1);
    glm::dvec2 acrossLow(1e300), acrossHigh(-1e300);
    for (const glm::dvec3& p : sheet.positions) {
      const glm::dvec2 q(glm::dot(p - boxCentre, e1), glm::dot(p - boxCentre, e2));
      acrossLow = glm::min(acrossLow, q);
      acrossHigh = glm::max(acrossHigh, q);
    }
    const glm::dvec2 acrossMiddle = 0.5 * (acrossLow + acrossHigh);
    const glm::dvec3 centre = boxCentre + acrossMiddle.x * e1 + acrossMiddle.y * e2;
    double lowest = 1e300, highest = -1e300, sum = 0.0, sumH = 0.0, sumHH = 0.0, sumHR = 0.0;
    std::vector<glm::dvec2> profile;
    profile.reserve(sheet.positions.size());
    for (const glm::dvec3& p : sheet.positions) {
      const double h = glm::dot(p - centre, d);
      const double r = glm::length((p - centre) - h * d);
      profile.emplace_back(h, r);
      lowest = std::min(lowest, h);
      highest = std::max(highest, h);
      sum += r;
      sumH += h;
      sumHH += h * h;
      sumHR += h * r;
    }
    const auto n = static_cast<double>(sheet.positions.size());
    const double radius = sum / n;
    if (!(radius > 0.0) || highest - lowest < 0.5 * radius) continue;
    const double meanH = sumH / n, varianceH = sumHH / n - meanH * meanH;
    const double slope = varianceH > 0.0 ? (sumHR / n - meanH * radius) / varianceH : 0.0;
    if (std::abs(slope) > steepestTaper) continue;
    double nearest = 1e300, farthest = -1e300;
    for (const glm::dvec2& hr : profile) {
      const double off = hr.y - (radius + slope * (hr.x - meanH));
      nearest = std::min(nearest, off);
      farthest = std::max(farthest, off);
    }
    const double spread = (farthest - nearest) / radius;
    if (spread <= kTubeSpread && spread < bestSpread) {
      bestSpread = spread;
      best = TubeAxis{RevolutionAxis{centre, d, spread}, radius};
    }
  }
  return best;
}

std::vector<FoldSuggestion> suggestTubeRings(const FoldSession& session, const FoldFitter& fitter,
                                             const RevolutionAxis& targetAxis,
                                             const std::vector<SurfaceSample>& targetSamples,
                                             std::size_t count, const Deadline& deadline,
                                             std::mt19937_64& random, std::size_t mostRings,
                                             const TubeChains* resume, TubeChains* grownOut) {
  if (count == 0 || mostRings == 0 || targetSamples.empty() || deadline.givesUp()) return {};
  const Sheet& sheet = session.fixed();
  const std::optional<TubeAxis> tube = tubeAbout(sheet, targetAxis.direction);
  if (!tube) return {};
  const RevolutionAxis& axis = tube->axis;

  const std::vector<FoldRecord> base(
      session.folds().begin(),
      session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount()));
  const double before = fitter.approximateDistance(sheet);
  auto measure = [&](const Sheet& folded) {
    const SurfaceDistance d =
        surfaceDistance(meshOf(folded), fitter.measuredTarget(), kMeasureSamples);
    return d.chamfer + kTubeHausdorffWeight * d.hausdorff;
  };
  const double measuredBefore = measure(sheet);
  const bool allowCrossing = fitter.settings().allowSelfIntersection;
  const std::size_t crossingsBefore =
      allowCrossing ? 0 : findSelfIntersections(sheet).intersections.size();
  // The two chains (see the header), grown on sessions of their own.
  struct Chain {
    std::span<const int> orders;
    std::unique_ptr<FoldSession> grown;
    double current = 0.0;
    std::vector<RingShape> kept;
    bool done = false;
  };
  std::vector<Chain> chains;
  for (const std::span<const int> orders :
       {std::span<const int>(kFineOrders), std::span<const int>(kAllOrders)}) {
    Chain chain;
    chain.orders = orders;
    chain.grown = std::make_unique<FoldSession>(session.initial());
    chain.grown->applyRecords(base);
    chain.current = measuredBefore;
    chains.push_back(std::move(chain));
  }
  // Chains handed on from an earlier call on this sheet: their rings remade, not searched again.
  if (resume && resume->sheet == sheet.positions)
    for (std::size_t c = 0; c < chains.size() && c < resume->chains.size(); ++c) {
      Chain& chain = chains[c];
      for (const RingShape& ring : resume->chains[c]) {
        if (chain.kept.size() >= mostRings) break;
        makeRing(*chain.grown, ringOf(ring, axis));
        chain.kept.push_back(ring);
      }
      if (!chain.kept.empty()) chain.current = measure(chain.grown->fixed());
    }

  // The chains grow side by side, a ring each per step, so that a step the clock cuts answers
  // both as far as they got. Each step's candidates are scored in two batches, the solved rings
  // (neckRings on the sheet as the rings before it left it) first, then the same at half a turn
  // and the corner rings (each ring of the chain turned by half a step); each is made on a
  // session of its own, checked for passing the sheet through itself and measured, and the
  // closest scored kept while it brings the sheet closer. Between batches the clock is read
  // (timed_batches.hpp): a batch the time left would not finish is not started, and what the
  // chains hold then, each ring made whole, is answered.
  TimedBatches batches(deadline);
  for (Chain& chain : chains) chain.done = chain.kept.size() >= mostRings;
  while (!batches.cut()) {
    for (Chain& chain : chains) {
      if (chain.done || batches.cut()) continue;
      FoldSession& grown = *chain.grown;
      const std::vector<SurfaceSample> samples =
          sampleSurface(meshOf(grown.fixed()), kProfileSamples, random());
      std::vector<RingShape> shapes;
      for (const double turn : {0.0, 0.5})
        for (RingShape shape : neckRings(samples, targetSamples, axis, 0.0, chain.orders)) {
          shape.turn = turn * 2.0 * std::numbers::pi / shape.order;
          shapes.push_back(shape);
        }
      const std::size_t solved = shapes.size() / 2;  // those at turn 0
      for (const RingShape& ring : chain.kept)
        for (const double inward : kCornerInward) {
          RingShape corner = ring;
          corner.turn += std::numbers::pi / ring.order;
          corner.radius *= inward;
          shapes.push_back(corner);
        }
      // The corners farthest out folded in where they stand out most (a neck), once per
      // distinct turn of the chain's rings.
      std::vector<std::pair<int, double>> turns;
      for (const RingShape& ring : chain.kept) {
        const double step = 2.0 * std::numbers::pi / ring.order;
        const double turn = std::fmod(ring.turn + 0.5 * step, step);
        const bool seen = std::any_of(turns.begin(), turns.end(), [&](const auto& t) {
          return t.first == ring.order && std::abs(t.second - turn) < 1e-9;
        });
        if (seen) continue;
        turns.emplace_back(ring.order, turn);
        for (const int side : {1, -1})
          for (const double depth : kCornerDepths)
            if (const std::optional<RingShape> corner =
                    neckCornerRing(samples, targetSamples, axis, ring.order, turn, side, depth))
              shapes.push_back(*corner);
      }
      std::vector<double> scores(shapes.size(), 1e300);
      RingTrials trials(grown, allowCrossing ? std::nullopt : std::optional(crossingsBefore));
      const auto evaluate = [&](std::size_t r) {
        if (deadline.passed()) return;
        deadline.countEvaluation();
        trials.tryRing(ringOf(shapes[r], axis), 1,
                       [&](const FoldSession& copy) { scores[r] = measure(copy.fixed()); });
      };
      const auto foldsOf = [&](std::size_t from, std::size_t to) {
        double folds = 0.0;
        for (std::size_t r = from; r < to; ++r) folds += shapes[r].order;
        return folds;
      };
      if (batches.run(0, solved, foldsOf(0, solved), evaluate))
        batches.run(solved, shapes.size(), foldsOf(solved, shapes.size()), evaluate);
      // The closest scored (a candidate the clock cut is unscored).
      const auto best = std::min_element(scores.begin(), scores.end());
      if (best == scores.end() || !(*best < chain.current)) {
        chain.done = true;
        continue;
      }
      const RingShape& chosen = shapes[static_cast<std::size_t>(best - scores.begin())];
      makeRing(grown, ringOf(chosen, axis));
      chain.kept.push_back(chosen);
      chain.current = *best;
      chain.done = chain.kept.size() >= mostRings;
    }
    if (std::all_of(chains.begin(), chains.end(), [](const Chain& c) { return c.done; })) break;
  }
  // Toward a cup whose floor the cone reaches past (floor_rings.hpp), each chain closed by the
  // floor ring that brings it nearest, where one brings it nearer (a chain handed on keeps its
  // rings alone: the floor is tried again after them).
  bool bareTried = false;
  for (Chain& chain : chains) {
    if (deadline.passed() || (chain.kept.empty() && std::exchange(bareTried, true))) continue;
    if (const std::optional<FloorRing> floor =
            bestFloorRing(*chain.grown, fitter, axis, targetSamples, chain.current, deadline)) {
      makeRing(*chain.grown, floor->ring);
      chain.current = floor->measured;
    }
  }
  if (deadline.isCancelled()) return {};
  if (grownOut) {
    grownOut->sheet = sheet.positions;
    grownOut->chains.clear();
    for (const Chain& chain : chains) grownOut->chains.push_back(chain.kept);
  }

  std::vector<FoldSuggestion> made;
  std::vector<double> measured;
  for (const Chain& chain : chains) {
    const FoldSession& grown = *chain.grown;
    if (grown.foldCount() == base.size() || !(chain.current < measuredBefore)) continue;
    FoldSuggestion suggestion;
    suggestion.folds.assign(grown.folds().begin() + static_cast<std::ptrdiff_t>(base.size()),
                            grown.folds().begin() + static_cast<std::ptrdiff_t>(grown.foldCount()));
    suggestion.sheet = grown.fixed();
    suggestion.before = before;
    suggestion.after = fitter.approximateDistance(suggestion.sheet);
    made.push_back(std::move(suggestion));
    measured.push_back(chain.current);
  }

  // Best first by the measure. Not filtered by the search's distance: it counts a far neck at a
  // tenth and every millimetre the rings' tilted cuts move a body already on the target in full,
  // so it can rise while the measure halves (a closed bottle: 0.00149 -> 0.00151 against 0.0156
  // -> 0.0083), and the chains were dropped; the step's score below is scaled by the measure.
  std::vector<std::size_t> order(made.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return measured[a] < measured[b]; });
  // The beam ranks steps by `after`: the search's distance before, scaled by the measure's fall
  // (the robust distance would rank a chain that leaves the neck wide first).
  std::vector<FoldSuggestion> out;
  for (std::size_t c : order) {
    made[c].after = std::min(made[c].after, before * measured[c] / measuredBefore);
    out.push_back(std::move(made[c]));
  }
  if (out.size() > count) out.resize(count);
  return out;
}

}  // namespace curvefold
