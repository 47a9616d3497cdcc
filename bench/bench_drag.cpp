// Drag update (fixed sheet + target -> temporal sheet) against a plain copy of the mesh arrays,
// on cylinders of about 10k, 100k and 1M triangles with 5 prior folds (docs/design.md 8); and the
// planar simplification that the display session makes after an undo, redo or open, on the
// folded cylinders and on a flat square of about 100k triangles (an unstructured mesh).
//
//   build/bench/bench_drag --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <map>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/planar_simplification.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

// Cylinder resolutions for ~10k / ~100k / ~1M triangles (see surfaces.hpp).
int resolutionFor(long triangles) {
  switch (triangles) {
    case 10'000:
      return 82;
    case 100'000:
      return 259;
    default:
      return 820;
  }
}

// A cylinder (axis y, radius 0.045, height 0.21) with five committed folds: corners and edges
// pushed in and bent over, the kind of start a designer has after a minute.
struct FoldedCylinder {
  explicit FoldedCylinder(long triangles)
      : session(makeSurface("cylinder", {{"resolution", resolutionFor(triangles)}})) {
    const double top = 0.105, r = 0.045;
    const std::vector<std::pair<glm::dvec3, glm::dvec3>> folds = {
        {{0.0, top, r}, {0.0, top - 0.04, 0.0}},        // front top pushed in
        {{r, -top, 0.0}, {0.01, -top + 0.03, 0.0}},     // side bottom pushed in
        {{-r, top, 0.0}, {-0.01, top - 0.05, 0.0}},     // other side top
        {{0.0, -top, -r}, {0.0, -top + 0.03, -0.005}},  // back bottom
        {{0.0, 0.0, r}, {0.0, 0.01, 0.03}},             // dent in the middle
    };
    for (const auto& [grab, target] : folds) {
      session.beginDragNear(grab);
      session.updateDrag(target);
      session.commit();
    }
  }
  FoldSession session;
};

FoldedCylinder& cylinder(long triangles) {
  static std::map<long, std::unique_ptr<FoldedCylinder>> cache;
  auto& slot = cache[triangles];
  if (!slot) slot = std::make_unique<FoldedCylinder>(triangles);
  return *slot;
}

void BM_DragUpdate(benchmark::State& state) {
  FoldSession& session = cylinder(state.range(0)).session;
  // Grab the middle of the top rim and swing it down: about a third of the sheet is reflected.
  const glm::dvec3 grabbed = session.beginDragNear({0.03, 0.105, 0.03});
  const glm::dvec3 targets[2] = {grabbed + glm::dvec3{0.0, -0.07, 0.01},
                                 grabbed + glm::dvec3{0.001, -0.071, 0.012}};
  std::size_t moved = 0, iteration = 0;
  for (auto _ : state) {
    const ReflectionChanges& changes = session.updateDrag(targets[iteration++ & 1]);
    moved = changes.movedVertices.size();
    benchmark::DoNotOptimize(session.current().positions.data());
  }
  // Memory while dragging, in sheets (the arrays of one temporal sheet).
  const SessionMemory memory = session.memoryUse();
  const double sheet = static_cast<double>(sheetBytes(session.current()));
  state.counters["pair_in_sheets"] = (memory.fixed + memory.temporal) / sheet;
  state.counters["all_in_sheets"] =
      (memory.fixed + memory.temporal + memory.adjacency + memory.workspace) / sheet;
  session.cancel();
  state.counters["triangles"] = static_cast<double>(session.fixed().triangleCount());
  state.counters["moved_vertices"] = static_cast<double>(moved);
}

void BM_CopyMeshArrays(benchmark::State& state) {
  const Sheet& fixed = cylinder(state.range(0)).session.fixed();
  Sheet copy;
  for (auto _ : state) {
    copy.positions = fixed.positions;
    copy.development = fixed.development;
    copy.triangles = fixed.triangles;
    benchmark::DoNotOptimize(copy.positions.data());
    benchmark::ClobberMemory();
  }
  state.counters["triangles"] = static_cast<double>(fixed.triangleCount());
}

void BM_SimplifyPlanar(benchmark::State& state) {
  const Sheet& fixed = cylinder(state.range(0)).session.fixed();
  std::size_t drawn = 0;
  for (auto _ : state) drawn = simplifyPlanar(fixed).sheet.triangleCount();
  state.counters["triangles"] = double(fixed.triangleCount());
  state.counters["simplified"] = double(drawn);
}

void BM_SimplifyPlanarFlatSquare(benchmark::State& state) {
  const Sheet square = makeSurface("square", {{"resolution", 150}});
  std::size_t drawn = 0;
  for (auto _ : state) drawn = simplifyPlanar(square).sheet.triangleCount();
  state.counters["triangles"] = double(square.triangleCount());
  state.counters["simplified"] = double(drawn);
}

BENCHMARK(BM_SimplifyPlanar)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SimplifyPlanarFlatSquare)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DragUpdate)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CopyMeshArrays)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
