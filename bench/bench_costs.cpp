// Costs that grew the wrong way (issue 13, E20-E23), each with the case that showed it:
//   unfolding an OBJ of separate pieces (was O(pieces x vertices)) against a connected grid;
//   validate() on a vertex with a huge fan (was O(valence^2));
//   a grab on a folded cylinder (was three scans of every triangle).
//
//   build/bench/bench_costs --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <cmath>
#include <map>
#include <numbers>

#include <benchmark/benchmark.h>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/unfold.hpp"
#include "engine/geometry/validate.hpp"
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
void BM_ValidateFan(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
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
  for (auto _ : state) validate(sheet);
  state.counters["triangles"] = n;
}
BENCHMARK(BM_ValidateFan)->Arg(20'000)->Arg(40'000)->Unit(benchmark::kMillisecond);

// Grab (and let go of) a point of a cylinder with a fold on it, picked as the interaction core
// picks it (its tree gives the surface point; here it is found once, outside the loop).
void BM_Grab(benchmark::State& state) {
  static std::map<long, std::unique_ptr<FoldSession>> sessions;
  auto& session = sessions[state.range(0)];
  if (!session) {
    const int resolution = state.range(0) == 10'000 ? 82 : 259;
    session = std::make_unique<FoldSession>(makeSurface("cylinder", {{"resolution", resolution}}));
    session->beginDragNear({0.0, 0.105, 0.045});
    session->updateDrag({0.0, 0.065, 0.0});
    session->commit();
  }
  const SurfacePoint point = closestSurfacePoint(session->fixed(), {0.031, -0.05, 0.031});
  for (auto _ : state) {
    benchmark::DoNotOptimize(session->beginDrag(point));
    session->cancel();
  }
  state.counters["triangles"] = double(session->fixed().triangleCount());
}
BENCHMARK(BM_Grab)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
