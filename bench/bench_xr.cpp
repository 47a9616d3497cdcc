// Per-frame CPU time of the XR loop without rendering (issue #5: <= 2 ms at 100k triangles, so a
// 90 Hz headset keeps its budget for drawing): xrWaitFrame/xrBeginFrame, xrSyncActions and the
// hands located at the display time, the interaction core (hover, drag update), the recorder,
// and xrEndFrame, through the real Khronos loader and the simulated runtime replaying 60 s of
// continuous two-handed dragging on a 100k-triangle cylinder (a headless XR_MND_headless
// session, so no frame is drawn).
//
//   build/bench/bench_xr --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <unistd.h>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <numbers>

#include <benchmark/benchmark.h>

#include "app/xr/xr_app.hpp"
#include "bench/dragging_session.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {
namespace {

namespace fs = std::filesystem;

struct XrLoop {
  fs::path dir;
  std::unique_ptr<cli::XrApp> app;

  XrLoop() {
    dir = fs::temp_directory_path() / ("curvefold-bench-xr-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path input = dir / "drag.jsonl";
    writeRecording(sixtySecondsOfDragging(259), input);  // ~100k triangles
    setenv("XR_RUNTIME_JSON", CURVEFOLD_SIM_RUNTIME_JSON, 1);
    setenv("CURVEFOLD_SIM_INPUT", input.c_str(), 1);
    setenv("CURVEFOLD_SIM_HOLD", "1", 1);  // never ends: the benchmark decides
    cli::XrAppOptions options;
    options.input = input.string();
    options.headless = true;
    options.record = (dir / "xr.jsonl").string();
    options.autosave = (dir / "xr.curvefold.json").string();
    app = std::make_unique<cli::XrApp>(options);
    if (!app->startSession()) throw std::runtime_error("the simulated runtime has no headset");
    // Up to FOCUSED, where frames start feeding the core.
    for (int i = 0; i < 100; ++i) {
      app->pollEvents();
      if (app->sessionRunning()) app->frame();
    }
  }
  ~XrLoop() {
    app.reset();
    fs::remove_all(dir);
  }
};

void BM_XrFrameWithoutRendering(benchmark::State& state) {
  static XrLoop loop;
  std::size_t dragging = 0, frames = 0;
  for (auto _ : state) {
    loop.app->pollEvents();
    loop.app->frame();
    dragging += loop.app->document().session->dragging();
    ++frames;
  }
  state.counters["dragging"] = double(dragging) / double(std::max<std::size_t>(frames, 1));
  state.counters["triangles"] = double(loop.app->document().session->current().triangleCount());
}
// 300 frames a repetition: 5 repetitions stay inside the 60 s (5,400 frames) of dragging.
BENCHMARK(BM_XrFrameWithoutRendering)->Iterations(300)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
