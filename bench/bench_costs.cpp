// Costs that grew the wrong way (issue 13, E20-E23), each with the case that showed it:
//   unfolding an OBJ of separate pieces (was O(pieces x vertices)) against a connected grid;
//   validate() on a vertex with a huge fan (was O(valence^2));
//   a grab on a folded cylinder (was three scans of every triangle);
//   the folded sheet a command-line fold starts from: the history replayed, or the cache's entry;
//   the crease pattern panel of a frame: built from the sheet (what the desktop did every frame)
//   or from the cache shared by the desktop and the headset;
//   whether a development overlaps itself on a fan of long spokes (was O(triangles^2) in a uniform
//   grid: 39.8 s at 20k triangles) against a square of a million short edges' worth.
//
//   build/bench/bench_costs --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numbers>
#include <random>

#include <benchmark/benchmark.h>

#include "app/desktop/interaction_scene.hpp"
#include "engine/geometry/development_overlap.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/unfold.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/sheet_cache.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

// n separate right triangles of 1 cm, in a row.
void BM_UnfoldSeparatePieces(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<glm::dvec3> positions;
  std::vector<Triangle> triangles;
  for (int i = 0; i < n; ++i) {
    const auto v = static_cast<VertexIndex>(positions.size());
    positions.insert(positions.end(),
                     {{0.02 * i, 0.0, 0.0}, {0.02 * i + 0.01, 0.0, 0.0}, {0.02 * i, 0.01, 0.0}});
    triangles.push_back({v, v + 1, v + 2});
  }
  for (auto _ : state) benchmark::DoNotOptimize(unfoldDevelopment(positions, triangles));
  state.counters["triangles"] = n;
}
BENCHMARK(BM_UnfoldSeparatePieces)->Arg(8'000)->Arg(32'000)->Unit(benchmark::kMillisecond);

// The same number of triangles as one connected grid.
void BM_UnfoldConnectedGrid(benchmark::State& state) {
  const Sheet sheet =
      makeSurface("square", {{"resolution", std::round(std::sqrt(state.range(0) / 2.0))}});
  for (auto _ : state)
    benchmark::DoNotOptimize(unfoldDevelopment(sheet.positions, sheet.triangles));
  state.counters["triangles"] = double(sheet.triangleCount());
}
BENCHMARK(BM_UnfoldConnectedGrid)->Arg(32'000)->Unit(benchmark::kMillisecond);

// A flat disk of n triangles around one centre vertex.
Sheet flatFan(int n) {
  Sheet sheet;
  sheet.positions.push_back({0.0, 0.0, 0.0});
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    sheet.positions.push_back({0.1 * std::cos(a), 0.1 * std::sin(a), 0.0});
  }
  for (const glm::dvec3& p : sheet.positions) sheet.development.push_back({p.x, p.y});
  for (int i = 0; i < n; ++i)
    sheet.triangles.push_back(
        {0, static_cast<VertexIndex>(1 + i), static_cast<VertexIndex>(1 + (i + 1) % n)});
  return sheet;
}

void BM_ValidateFan(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Sheet sheet = flatFan(n);
  for (auto _ : state) validate(sheet);
  state.counters["triangles"] = n;
}
BENCHMARK(BM_ValidateFan)->Arg(20'000)->Arg(40'000)->Unit(benchmark::kMillisecond);

// Whether the development overlaps itself (OBJ import, `check`): a fan's long spokes, then a
// square of about a million triangles (about 5 resolution^2 of them).
void BM_DevelopmentCrossingFan(benchmark::State& state) {
  const Sheet sheet = flatFan(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(findDevelopmentCrossing(sheet));
  state.counters["triangles"] = double(sheet.triangleCount());
}
BENCHMARK(BM_DevelopmentCrossingFan)
    ->Arg(5'000)
    ->Arg(20'000)
    ->Arg(40'000)
    ->Unit(benchmark::kMillisecond);

// The self-intersection test of `check` on a fan: every pair of its triangles shares the centre,
// so every pair's boxes meet (issue 40: 0.74 / 2.9 / 11.5 / 45.8 s at 5k / 10k / 20k / 40k).
void BM_SelfIntersectionFan(benchmark::State& state) {
  const Sheet sheet = flatFan(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(findSelfIntersections(sheet));
  state.counters["triangles"] = double(sheet.triangleCount());
}
BENCHMARK(BM_SelfIntersectionFan)
    ->Arg(5'000)
    ->Arg(10'000)
    ->Arg(20'000)
    ->Arg(40'000)
    ->Unit(benchmark::kMillisecond);

void BM_DevelopmentCrossingSquare(benchmark::State& state) {
  const Sheet sheet =
      makeSurface("square", {{"resolution", std::round(std::sqrt(state.range(0) / 5.0))}});
  for (auto _ : state) benchmark::DoNotOptimize(findDevelopmentCrossing(sheet));
  state.counters["triangles"] = double(sheet.triangleCount());
}
BENCHMARK(BM_DevelopmentCrossingSquare)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// A cylinder of about 10k (resolution 82) or 100k (259) triangles with one fold on it.
std::unique_ptr<FoldSession> foldedCylinder(int resolution) {
  auto session =
      std::make_unique<FoldSession>(makeSurface("cylinder", {{"resolution", resolution}}));
  session->beginDragNear({0.0, 0.105, 0.045});
  session->updateDrag({0.0, 0.065, 0.0});
  session->commit();
  return session;
}

// Grab (and let go of) a point of a cylinder with a fold on it, picked as the interaction core
// picks it (its tree gives the surface point; here it is found once, outside the loop).
void BM_Grab(benchmark::State& state) {
  static std::map<long, std::unique_ptr<FoldSession>> sessions;
  auto& session = sessions[state.range(0)];
  if (!session) session = foldedCylinder(state.range(0) == 10'000 ? 82 : 259);
  const SurfacePoint point = closestSurfacePoint(session->fixed(), {0.031, -0.05, 0.031});
  for (auto _ : state) {
    benchmark::DoNotOptimize(session->beginDrag(point));
    session->cancel();
  }
  state.counters["triangles"] = double(session->fixed().triangleCount());
}
BENCHMARK(BM_Grab)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

// A frame's crease pattern panel on a 100k-triangle cylinder with a fold: built from the sheet
// (argument 0) or taken from the cache (argument 1).
void BM_CreasePatternPanelPerFrame(benchmark::State& state) {
  const std::unique_ptr<FoldSession> folded = foldedCylinder(259);
  const FoldSession& session = *folded;
  const SceneColors colors;
  desktop::CreasePatternCache cache;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      benchmark::DoNotOptimize(creasePatternPanel(session.fixed(), colors));
    } else {
      const CreasePatternPanel copy = cache.panelFor(session, colors);  // as a scene holds it
      benchmark::DoNotOptimize(copy);
    }
  }
  state.counters["triangles"] = double(session.fixed().triangleCount());
}
BENCHMARK(BM_CreasePatternPanelPerFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// A frame's crease lines (the 3D view's creases) on the same sheet.
void BM_CreaseLinesPerFrame(benchmark::State& state) {
  const std::unique_ptr<FoldSession> folded = foldedCylinder(259);
  const FoldSession& session = *folded;
  const SceneColors colors;
  for (auto _ : state)
    benchmark::DoNotOptimize(creaseLines(session.fixed(), glm::mat4(1.0f), colors));
  state.counters["triangles"] = double(session.fixed().triangleCount());
}
BENCHMARK(BM_CreaseLinesPerFrame)->Unit(benchmark::kMillisecond);

// A design of `folds` folds on a cylinder of about 100k triangles, and what a command-line fold
// pays to get its folded sheet: the replay of the whole history, or the cache's entry.
const Design& cylinderDesign(int folds) {
  static std::map<int, Design> designs;
  Design& design = designs[folds];
  if (!design.folds.empty()) return design;
  const GeneratedSurface surface{"cylinder", {{"resolution", 259}}};
  FoldSession session(makeSurface(surface.generator, surface.parameters));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  while (session.foldCount() < std::size_t(folds)) {
    const double a = 2.0 * std::numbers::pi * unit(random), y = 0.2 * unit(random) - 0.1;
    const glm::dvec3 grabbed = session.beginDragNear({0.045 * std::cos(a), y, 0.045 * std::sin(a)});
    session.updateDrag(
        grabbed + 0.03 * glm::dvec3(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5));
    session.commit();
  }
  design = Design{surface, session.folds()};
  return design;
}

void BM_FoldCommandReplay(benchmark::State& state) {
  const Design& design = cylinderDesign(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(buildSheet(design));
  state.counters["folds"] = double(design.folds.size());
}
BENCHMARK(BM_FoldCommandReplay)->Arg(10)->Arg(40)->Unit(benchmark::kMillisecond);

void BM_FoldCommandCached(benchmark::State& state) {
  const Design& design = cylinderDesign(static_cast<int>(state.range(0)));
  storeCachedSheet(design, buildSheet(design));
  for (auto _ : state) benchmark::DoNotOptimize(loadCachedSheet(design));
  state.counters["folds"] = double(design.folds.size());
}
BENCHMARK(BM_FoldCommandCached)->Arg(10)->Arg(40)->Unit(benchmark::kMillisecond);

// Issue 28: the symmetries a studio panel lists for a cylinder, found on the frame that opens the
// list (resolution 48 is the default).
void BM_SymmetryChoices(benchmark::State& state) {
  const Sheet cylinder = makeSurface("cylinder", {{"resolution", double(state.range(0))}});
  for (auto _ : state) benchmark::DoNotOptimize(symmetryChoices(cylinder));
  state.counters["vertices"] = double(cylinder.vertexCount());
}
BENCHMARK(BM_SymmetryChoices)->Arg(48)->Arg(200)->Arg(500)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace curvefold

int main(int argc, char** argv) {
  // The cache's entries go to a scratch folder, not the user's.
  const std::string cache = "/tmp/curvefold-bench-cache-" + std::to_string(::getpid());
  ::setenv("CURVEFOLD_CACHE_DIR", cache.c_str(), 1);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove_all(cache);
  return 0;
}
