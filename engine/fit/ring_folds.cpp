#include "engine/fit/ring_folds.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <Eigen/Dense>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <nlopt.hpp>

#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/self_intersection.hpp"

namespace curvefold {
namespace {

// Sheet samples the chains are previewed on; a tube's radius spread allowed; evaluations of the
// joint refinement per chain.
constexpr std::size_t kPreviewSamples = 1200;
constexpr double kTubeSpread = 0.03;
constexpr int kJointEvaluations = 400;
// Samples a side of the Chamfer distance rings made on the sheet are chosen by: the search's
// robust distance caps far points, and a tube's untouched neck is all far points.
constexpr std::size_t kMeasureSamples = 1500;
// The tube's axis and the target's are one direction (cosine of the angle between them).
constexpr double kSameDirection = 0.98;

struct Preview {
  std::vector<glm::dvec3> points, normals;
};

std::vector<SurfaceSample> samplesOf(const Preview& preview) {
  std::vector<SurfaceSample> samples(preview.points.size());
  for (std::size_t i = 0; i < samples.size(); ++i)
    samples[i] = {preview.points[i], preview.normals[i]};
  return samples;
}

Preview previewed(Preview preview, const std::vector<RingShape>& chain,
                  const RevolutionAxis& axis) {
  for (const RingShape& shape : chain)
    previewRing(ringOf(shape, axis), preview.points, preview.normals);
  return preview;
}

// The least distance from the axis of a ring's planes over heights [lo, hi] (its deepest cut:
// a plane tilted by beta through (h, rho) meets the tube's wall at rho - (t - h) tan(beta)).
double deepestCut(const RingShape& shape, double lo, double hi) {
  const double slope = std::tan(shape.tilt);
  return std::min(shape.radius - (lo - shape.height) * slope,
                  shape.radius - (hi - shape.height) * slope);
}

}  // namespace

std::optional<TubeAxis> tubeAbout(const Sheet& sheet, const glm::dvec3& direction) {
  if (sheet.positions.size() < 4) return std::nullopt;
  // The middle of its bounding box: a tube's seam has its vertices twice, which pulls the
  // centroid toward it.
  glm::dvec3 low(1e300), high(-1e300);
  for (const glm::dvec3& p : sheet.positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const glm::dvec3 centre = 0.5 * (low + high);
  // The tube's own axis: of the given direction and the vertices' principal axes, the one about
  // which the radius varies least (a start placed from other samples lies a little off the
  // target's axis, and a tube as long as it is wide has no distinct principal axis).
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const glm::dvec3& p : sheet.positions) {
    const Eigen::Vector3d d(p.x - centre.x, p.y - centre.y, p.z - centre.z);
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  std::vector<glm::dvec3> candidates{glm::normalize(direction)};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = solver.eigenvectors().col(k);
    candidates.emplace_back(e.x(), e.y(), e.z());
  }
  std::optional<TubeAxis> best;
  double bestSpread = 1e300;
  for (const glm::dvec3& d : candidates) {
    if (std::abs(glm::dot(d, glm::normalize(direction))) < kSameDirection) continue;
    double lowest = 1e300, highest = -1e300, nearest = 1e300, farthest = 0.0, sum = 0.0;
    for (const glm::dvec3& p : sheet.positions) {
      const double h = glm::dot(p - centre, d);
      const double r = glm::length((p - centre) - h * d);
      lowest = std::min(lowest, h);
      highest = std::max(highest, h);
      nearest = std::min(nearest, r);
      farthest = std::max(farthest, r);
      sum += r;
    }
    const double radius = sum / static_cast<double>(sheet.positions.size());
    if (!(radius > 0.0) || highest - lowest < 0.5 * radius) continue;
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
                                             std::mt19937_64& random, std::size_t mostRings) {
  if (count == 0 || mostRings == 0 || targetSamples.empty() || deadline.givesUp()) return {};
  const Sheet& sheet = session.fixed();
  const std::optional<TubeAxis> tube = tubeAbout(sheet, targetAxis.direction);
  if (!tube) return {};
  const RevolutionAxis& axis = tube->axis;

  const TriangleMesh mesh = meshOf(sheet);
  Preview start;
  for (const SurfaceSample& s : sampleSurface(mesh, kPreviewSamples, random())) {
    start.points.push_back(s.position);
    start.normals.push_back(s.normal);
  }
  if (start.points.empty()) return {};
  const double spacing =
      0.5 * std::sqrt(surfaceArea(mesh) / static_cast<double>(start.points.size()));
  auto score = [&](const std::vector<RingShape>& chain) {
    deadline.countEvaluation();
    const Preview p = previewed(start, chain, axis);
    return fitter.approximateDistance(p.points, p.normals, spacing);
  };
  const double unfolded = score({});
  double lo = 1e300, hi = -1e300;
  for (const glm::dvec3& p : start.points) {
    lo = std::min(lo, glm::dot(p - axis.point, axis.direction));
    hi = std::max(hi, glm::dot(p - axis.point, axis.direction));
  }

  // A greedy chain on the preview, of mixed orders (0: any; one order each was tried and lost on
  // the example vase, made as they were).
  const std::vector<int> orders{0};
  std::vector<std::vector<RingShape>> chains(orders.size());
  std::vector<double> chainScores(orders.size(), unfolded);
  tbb::parallel_for(std::size_t(0), orders.size(), [&](std::size_t c) {
    std::vector<RingShape>& chain = chains[c];
    Preview now = start;
    for (std::size_t step = 0; step < mostRings && !deadline.passed(); ++step) {
      const std::vector<SurfaceSample> samples = samplesOf(now);
      double best = chainScores[c];
      std::optional<RingShape> chosen;
      for (const double turn : {0.0, 0.5})
        for (RingShape shape : neckRings(samples, targetSamples, axis)) {
          if (orders[c] != 0 && shape.order != orders[c]) continue;
          shape.turn = turn * 2.0 * std::numbers::pi / shape.order;
          std::vector<RingShape> trial = chain;
          trial.push_back(shape);
          if (const double s = score(trial); s < best) {
            best = s;
            chosen = shape;
          }
        }
      if (!chosen) break;
      chain.push_back(*chosen);
      chainScores[c] = best;
      now = previewed(now, {*chosen}, axis);
    }
  });
  if (deadline.givesUp()) return {};

  // Each chain refined as a whole: every ring's height, radius and tilt together.
  tbb::parallel_for(std::size_t(0), chains.size(), [&](std::size_t c) {
    std::vector<RingShape>& chain = chains[c];
    if (chain.empty() || deadline.passed()) return;
    // No ring cuts deeper than solved (past the depth where its wedges meet they cross).
    std::vector<double> floors;
    for (const RingShape& shape : chain) floors.push_back(deepestCut(shape, lo, hi));
    struct Objective {
      std::vector<RingShape>* best;
      double* bestScore;
      const decltype(score)* evaluate;
      const Deadline* deadline;
      nlopt::opt* optimizer;
      const std::vector<double>* floors;
      double lo, hi;
    };
    nlopt::opt optimizer(nlopt::LN_SBPLX, static_cast<unsigned>(3 * chain.size()));
    Objective objective{&chain, &chainScores[c], &score, &deadline, &optimizer, &floors, lo, hi};
    optimizer.set_min_objective(
        [](const std::vector<double>& x, std::vector<double>&, void* data) {
          auto& o = *static_cast<Objective*>(data);
          if (o.deadline->passed()) o.optimizer->force_stop();
          std::vector<RingShape> trial = *o.best;
          for (std::size_t r = 0; r < trial.size(); ++r) {
            trial[r].height = x[3 * r];
            trial[r].radius = x[3 * r + 1];
            trial[r].tilt = x[3 * r + 2];
            if (!(std::abs(trial[r].tilt) < 1.2) ||
                deepestCut(trial[r], o.lo, o.hi) < (*o.floors)[r])
              return 1e30;
          }
          const double s = (*o.evaluate)(trial);
          if (s < *o.bestScore) {
            *o.bestScore = s;
            *o.best = trial;
          }
          return std::isfinite(s) ? s : 1e30;
        },
        &objective);
    std::vector<double> x, steps;
    for (const RingShape& shape : chain) {
      x.insert(x.end(), {shape.height, shape.radius, shape.tilt});
      steps.insert(steps.end(), {0.05 * tube->radius, 0.02 * tube->radius, 0.05});
    }
    optimizer.set_initial_step(steps);
    optimizer.set_maxeval(kJointEvaluations);
    double value = 0.0;
    try {
      optimizer.optimize(x, value);
    } catch (const nlopt::forced_stop&) {
    } catch (const nlopt::roundoff_limited&) {
    }
  });
  if (deadline.givesUp()) return {};

  // Each chain made on the sheet, ring after ring; the closest prefix that does not pass the
  // sheet through itself is its suggestion.
  const std::vector<FoldRecord> base(
      session.folds().begin(),
      session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount()));
  const double before = fitter.approximateDistance(sheet);
  auto measure = [&](const Sheet& folded) {
    return surfaceDistance(meshOf(folded), fitter.target(), kMeasureSamples).chamfer;
  };
  const double measuredBefore = measure(sheet);
  const bool allowCrossing = fitter.settings().allowSelfIntersection;
  const std::size_t crossingsBefore =
      allowCrossing ? 0 : findSelfIntersections(sheet).intersections.size();
  std::vector<FoldSuggestion> made(chains.size());
  std::vector<double> measured(chains.size(), measuredBefore);
  tbb::parallel_for(std::size_t(0), chains.size(), [&](std::size_t c) {
    if (chains[c].empty() || deadline.passed()) return;
    FoldSession own(session.initial());
    own.applyRecords(base);
    double best = measuredBefore;
    std::size_t bestFolds = base.size();
    for (const RingShape& shape : chains[c]) {
      if (deadline.passed()) break;
      deadline.countEvaluation();
      const std::size_t foldsBefore = own.foldCount();
      // A ring that passes the sheet through itself is tried again shallower (its planes moved
      // out by a quarter, a half and three quarters of its deepest cut), then given up.
      bool crossed = false;
      const double depth = std::max(0.0, tube->radius - deepestCut(shape, lo, hi));
      for (int shallower = 0; shallower < 4; ++shallower) {
        RingShape tried = shape;
        tried.radius += 0.25 * shallower * depth;
        if (makeRing(own, ringOf(tried, axis)) == 0) break;
        crossed = !allowCrossing &&
                  findSelfIntersections(own.fixed()).intersections.size() > crossingsBefore;
        if (!crossed) break;
        while (own.foldCount() > foldsBefore) own.undo();
      }
      if (own.foldCount() == foldsBefore) {
        if (crossed) break;
        continue;
      }
      if (const double d = measure(own.fixed()); d < best) {
        best = d;
        bestFolds = own.foldCount();
      }
    }
    while (own.foldCount() > bestFolds) own.undo();
    if (bestFolds == base.size()) return;
    made[c].folds.assign(own.folds().begin() + static_cast<std::ptrdiff_t>(base.size()),
                         own.folds().begin() + static_cast<std::ptrdiff_t>(own.foldCount()));
    made[c].sheet = own.fixed();
    made[c].before = before;
    made[c].after = fitter.approximateDistance(made[c].sheet);
    measured[c] = best;
  });
  if (deadline.givesUp()) return {};

  // Beside the previewed chains, one grown on the sheet itself: at each step every solved ring
  // (neckRings on the sheet as the rings before it left it, at two turns) made, checked for
  // passing through itself and scored; the closest kept. Slower than a preview, but it sees which
  // parts each fold takes.
  {
    FoldSession grown(session.initial());
    grown.applyRecords(base);
    double current = measuredBefore;
    for (std::size_t step = 0; step < mostRings && !deadline.passed(); ++step) {
      const std::vector<FoldRecord> chain(
          grown.folds().begin(),
          grown.folds().begin() + static_cast<std::ptrdiff_t>(grown.foldCount()));
      const std::vector<SurfaceSample> samples =
          sampleSurface(meshOf(grown.fixed()), kPreviewSamples, random());
      std::vector<RingShape> shapes;
      for (const double turn : {0.0, 0.5})
        for (RingShape shape : neckRings(samples, targetSamples, axis)) {
          shape.turn = turn * 2.0 * std::numbers::pi / shape.order;
          shapes.push_back(shape);
        }
      std::vector<double> scores(shapes.size(), 1e300);
      tbb::enumerable_thread_specific<std::unique_ptr<FoldSession>> sessions;
      tbb::parallel_for(std::size_t(0), shapes.size(), [&](std::size_t r) {
        if (deadline.passed()) return;
        deadline.countEvaluation();
        std::unique_ptr<FoldSession>& local = sessions.local();
        if (!local) {
          local = std::make_unique<FoldSession>(session.initial());
          local->applyRecords(chain);
        }
        if (makeRing(*local, ringOf(shapes[r], axis)) > 0 &&
            (allowCrossing ||
             findSelfIntersections(local->fixed()).intersections.size() <= crossingsBefore))
          scores[r] = measure(local->fixed());
        while (local->foldCount() > chain.size()) local->undo();
      });
      const auto best = std::min_element(scores.begin(), scores.end());
      if (best == scores.end() || !(*best < current)) break;
      makeRing(grown, ringOf(shapes[static_cast<std::size_t>(best - scores.begin())], axis));
      current = *best;
    }
    if (deadline.givesUp()) return {};
    if (grown.foldCount() > base.size() && current < measuredBefore) {
      FoldSuggestion suggestion;
      suggestion.folds.assign(
          grown.folds().begin() + static_cast<std::ptrdiff_t>(base.size()),
          grown.folds().begin() + static_cast<std::ptrdiff_t>(grown.foldCount()));
      suggestion.sheet = grown.fixed();
      suggestion.before = before;
      suggestion.after = fitter.approximateDistance(suggestion.sheet);
      made.push_back(std::move(suggestion));
      measured.push_back(current);
    }
  }
  // Best first by the Chamfer distance; each closer by the search's distance too (or the fit
  // would not keep it).
  std::vector<std::size_t> order;
  for (std::size_t c = 0; c < made.size(); ++c)
    if (!made[c].folds.empty() && made[c].after < before && measured[c] < measuredBefore)
      order.push_back(c);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return measured[a] < measured[b]; });
  // The beam ranks steps by `after`: the search's distance before, scaled by the Chamfer
  // distance's fall (the robust distance would rank a chain that leaves the neck wide first).
  std::vector<FoldSuggestion> out;
  for (std::size_t c : order) {
    made[c].after = std::min(made[c].after, before * measured[c] / measuredBefore);
    out.push_back(std::move(made[c]));
  }
  if (out.size() > count) out.resize(count);
  return out;
}

}  // namespace curvefold
