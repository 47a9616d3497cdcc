// Rendering on whatever Vulkan device the loader finds (lavapipe on a machine without a GPU),
// 1280x720 (docs/design.md 8); the second argument is the sample count: 1 (what the designer window
// uses on a CPU device) or 4 (4x MSAA, the GPU default and the PNG renders):
// - BM_Frame: one frame of a static ~100k-triangle cylinder, submit to fence; no readback. The
//   third argument: 0 draws every triangle of the sheet (the renderer's cost per triangle), 1
//   draws it as the designer, replay and XR do (its DisplaySession: planar regions merged).
// - BM_FrameWithReadback: the same plus the copy to host memory and the pixels' memcpy.
// - BM_DragFrame: drag update + scene (creases, reflected part) + incremental upload + frame, end
//   to end, at ~10k and ~100k triangles, drawing every triangle (third argument 0) or the display
//   session (1); counters: sheet bytes uploaded per update and the bytes of the whole mesh drawn.
//
//   build-render/bench/bench_render --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "engine/geometry/fold_session.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/render/sheet_tracker.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

// Cylinder resolutions for ~10k / ~100k triangles (see surfaces.hpp).
int resolutionFor(long triangles) {
  return triangles <= 10'000 ? 82 : 259;
}

// One renderer per sample count, made on first use (a Vulkan context each).
HeadlessRenderer& renderer(long samples) {
  static std::map<long, std::unique_ptr<HeadlessRenderer>> renderers;
  std::unique_ptr<HeadlessRenderer>& r = renderers[samples];
  if (!r) {
    HeadlessOptions options;
    options.width = 1280;
    options.height = 720;
    options.samples = static_cast<VkSampleCountFlagBits>(samples);
    r = std::make_unique<HeadlessRenderer>(options);
  }
  return *r;
}

void labelDevice(benchmark::State& state, HeadlessRenderer& r) {
  state.counters["samples"] = double(r.samples());
  state.SetLabel(r.context().deviceName());
}

void staticFrame(benchmark::State& state, bool readback) {
  const FoldSession session(
      makeSurface("cylinder", {{"resolution", resolutionFor(state.range(0))}}));
  const Sheet& sheet = session.current();
  Scene scene = sceneForSheet(sheet, ViewPreset::Iso, 1280.0f / 720.0f, false);
  HeadlessRenderer& r = renderer(state.range(1));
  r.sceneRenderer().markSheetReplaced();
  SessionSheetTracker tracker;
  if (state.range(2) == 1) {
    tracker.update(session, r.sceneRenderer());
    tracker.describe(scene.sheet);
  }
  r.draw(scene);
  r.draw(scene);  // both frame slots hold the sheet
  for (auto _ : state) {
    if (readback)
      benchmark::DoNotOptimize(r.render(scene).pixels.data());
    else
      r.draw(scene);
  }
  state.counters["triangles"] = double(sheet.triangleCount());
  state.counters["drawn"] = double(scene.sheet.sheet->triangleCount());
  labelDevice(state, r);
}

void BM_Frame(benchmark::State& state) {
  staticFrame(state, false);
}
BENCHMARK(BM_Frame)
    ->ArgsProduct({{10'000, 100'000}, {1, 4}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_FrameWithReadback(benchmark::State& state) {
  staticFrame(state, true);
}
BENCHMARK(BM_FrameWithReadback)
    ->Args({100'000, 4, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_DragFrame(benchmark::State& state) {
  FoldSession session(makeSurface("cylinder", {{"resolution", resolutionFor(state.range(0))}}));
  HeadlessRenderer& r = renderer(state.range(1));
  SessionSheetTracker tracker(/*simplify=*/state.range(2) == 1);
  const Camera camera =
      frameBounds(worldBounds(session.initial()), ViewPreset::Iso, 1280.0f / 720.0f);
  const Ground ground = groundBelow(worldBounds(session.initial()));
  // Grab the middle of the top rim and swing it down: about a third of the sheet is reflected.
  const glm::dvec3 grabbed = session.beginDragNear({0.03, 0.105, 0.03});
  auto frame = [&](int step) {
    const double t = 0.02 + 0.002 * (step % 10);
    session.updateDrag(grabbed + glm::dvec3(-t, -2.0 * t, 0.5 * t));
    tracker.update(session, r.sceneRenderer());
    Scene scene;
    scene.camera = camera;
    scene.ground = ground;
    tracker.describe(scene.sheet);
    scene.creases = creaseLines(session.current(), glm::mat4(1.0f), scene.colors);
    r.draw(scene);
  };
  frame(0);
  frame(1);
  double bytes = 0.0, full = 0.0;
  int step = 2;
  for (auto _ : state) {
    frame(step++);
    bytes += double(r.sceneRenderer().lastUpload().sheetBytes);
    full = double(r.sceneRenderer().lastUpload().fullSheetBytes);
  }
  state.counters["triangles"] = double(session.current().triangleCount());
  state.counters["drawn"] = double(tracker.display().sheet().triangleCount());
  state.counters["upload_bytes"] = benchmark::Counter(bytes, benchmark::Counter::kAvgIterations);
  state.counters["mesh_bytes"] = full;
  labelDevice(state, r);
  session.cancel();
}
BENCHMARK(BM_DragFrame)
    ->ArgsProduct({{10'000, 100'000}, {1, 4}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
