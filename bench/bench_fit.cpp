// Folding toward a goal (issue 27, 4): one suggestion on a 10k-triangle sheet (target 2 s on a
// 2-core machine), a fit of 4 folds (target 60 s), and the distance a user checks.
//
//   build/bench/bench_fit --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <map>

#include <benchmark/benchmark.h>

#include "engine/fit/fold_fit.hpp"
#include "engine/fit/surface_distance.hpp"
#include "tests/support/random_fold_target.hpp"

namespace curvefold {
namespace {

// The default cylinder at resolution 82: 10k triangles (surfaces.hpp), folded at random.
const RandomFoldTarget& cylinderTarget(std::size_t folds) {
  static std::map<std::size_t, RandomFoldTarget> targets;
  auto it = targets.find(folds);
  if (it == targets.end())
    it = targets
             .emplace(folds,
                      makeRandomFoldTarget("cylinder", {{"resolution", 82}}, folds, 4000 + folds))
             .first;
  return it->second;
}

// The next fold for an unfolded 10k sheet toward a 2-fold target, as the studio asks for it.
void BM_SuggestFold(benchmark::State& state) {
  const RandomFoldTarget& target = cylinderTarget(2);
  const FoldFitter fitter(meshOf(target.sheet));
  FoldSession session(target.initial);
  std::vector<FoldSuggestion> found;
  for (auto _ : state) found = fitter.suggest(session, 1);
  state.counters["triangles"] = static_cast<double>(target.initial.triangleCount());
  state.counters["suggestions"] = static_cast<double>(found.size());
  state.counters["after_over_before"] = found.empty() ? 1.0 : found[0].after / found[0].before;
}
// CPU: of the whole process (every thread of the search), so a loaded machine's wall time can be
// told from the work done.
BENCHMARK(BM_SuggestFold)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();

// The suggestion's quality and cost toward targets unlike the bench's own (issue 38, 3): a
// 3-fold cone and a 2-fold swept curve, 10k triangles each; after_over_before: the best
// suggestion's distance (the search's) over the sheet's before it, lower is better.
void BM_SuggestFoldOn(benchmark::State& state) {
  static const RandomFoldTarget cone = makeRandomFoldTarget("cone", {{"resolution", 135}}, 3, 3000);
  static const RandomFoldTarget swept =
      makeRandomFoldTarget("swept_curve", {{"resolution", 77}}, 2, 2007);
  const RandomFoldTarget& target = state.range(0) == 0 ? cone : swept;
  const FoldFitter fitter(meshOf(target.sheet));
  FoldSession session(target.initial);
  std::vector<FoldSuggestion> found;
  for (auto _ : state) found = fitter.suggest(session, 1);
  state.counters["triangles"] = static_cast<double>(target.initial.triangleCount());
  state.counters["after_over_before"] = found.empty() ? 1.0 : found[0].after / found[0].before;
}
BENCHMARK(BM_SuggestFoldOn)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->MeasureProcessCPUTime();

// The same with the target's creases ignored: the search alone.
void BM_SuggestFoldBySearchAlone(benchmark::State& state) {
  const RandomFoldTarget& target = cylinderTarget(2);
  FitSettings settings;
  settings.useCreases = false;
  const FoldFitter fitter(meshOf(target.sheet), settings);
  FoldSession session(target.initial);
  for (auto _ : state) benchmark::DoNotOptimize(fitter.suggest(session, 1));
}
BENCHMARK(BM_SuggestFoldBySearchAlone)->Unit(benchmark::kMillisecond)->Iterations(1);

// A whole fit of a 4-fold target on the 10k sheet: by unfolding the target (arg 1), or by the
// beam search alone (arg 0).
void BM_FitFourFolds(benchmark::State& state) {
  const RandomFoldTarget& target = cylinderTarget(4);
  FitSettings settings;
  settings.useCreases = state.range(0) != 0;
  const FoldFitter fitter(meshOf(target.sheet), settings);
  double hausdorff = 0.0, folds = 0.0;
  for (auto _ : state) {
    FoldSession session(target.initial);
    FitOptions options;
    options.maxFolds = 4;
    const FitResult result = fitFolds(session, fitter, options);
    hausdorff = result.steps.back().hausdorff / result.steps.back().diagonal;
    folds = static_cast<double>(result.steps.size() - 1);
  }
  state.counters["relative_hausdorff"] = hausdorff;
  state.counters["folds"] = folds;
}
BENCHMARK(BM_FitFourFolds)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(1);

// `curvefold distance` of the 10k sheets, 20k samples a side.
void BM_Distance(benchmark::State& state) {
  const RandomFoldTarget& target = cylinderTarget(2);
  const TriangleMesh a = meshOf(target.initial), b = meshOf(target.sheet);
  for (auto _ : state) benchmark::DoNotOptimize(surfaceDistance(a, b));
}
BENCHMARK(BM_Distance)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
