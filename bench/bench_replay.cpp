// Replay of a 60 s, 90 Hz recording of continuous two-handed dragging on a 20k-triangle sheet,
// without rendering (DESIGN.md 8: < 1 s), with and without parsing the JSON Lines text.
//
//   build/bench/bench_replay --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <cmath>
#include <numbers>
#include <sstream>

#include <benchmark/benchmark.h>

#include "sim_input/gestures.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {
namespace {

// Twelve drags of about 4.7 s around the rim of a cylinder (~20k triangles), each along a
// wavering path, every other one while the other hand turns the sheet: 60 s of dragging.
const Recording& sixtySecondsOfDragging() {
  static const Recording recording = [] {
    RecordingHeader header;
    header.surface = GeneratedSurface{"cylinder", {{"resolution", 116}}};
    header.sheetFrame = {{0.0, 1.1, -0.45}, glm::dquat(1, 0, 0, 0)};
    header.rate = 90.0;
    GestureRecorder recorder(header);
    const double r = 0.045, top = 0.105;
    for (int i = 0; i < 12; ++i) {
      const double angle = i * 2.0 * std::numbers::pi / 12.0 + 0.1;
      const double end = (i % 2 == 0) ? top : -top;
      const glm::dvec3 grab{r * std::sin(angle), end, r * std::cos(angle)};
      const glm::dvec3 inward{-0.5 * grab.x, -0.5 * end, -0.5 * grab.z};
      std::vector<glm::dvec3> path;
      for (int k = 1; k <= 6; ++k) {
        const double s = k / 6.0;
        path.push_back(grab + s * inward + glm::dvec3(0.01 * std::sin(3 * s), 0.0, 0.01 * s));
      }
      std::optional<SheetTurn> turn;
      if (i % 2 == 1) turn = SheetTurn{{0.0, 1.0, 0.0}, 20.0};
      recorder.drag(grab, path, 4.7, turn);
    }
    return recorder.recording();
  }();
  return recording;
}

std::string asText(const Recording& recording) {
  std::string text = headerLine(recording.header) + "\n";
  for (const InputFrame& frame : recording.frames) text += frameLine(frame) + "\n";
  return text;
}

void BM_Replay(benchmark::State& state) {
  const Recording& recording = sixtySecondsOfDragging();
  std::size_t folds = 0;
  for (auto _ : state) {
    const ReplayResult result = replayRecording(recording);
    folds = result.design.folds.size();
    benchmark::DoNotOptimize(result.sheet.positions.data());
  }
  state.counters["frames"] = static_cast<double>(recording.frames.size());
  state.counters["seconds_recorded"] = recording.frames.back().time;
  state.counters["folds"] = static_cast<double>(folds);
  state.counters["triangles_at_start"] =
      static_cast<double>(initialSheet(Design{recording.header.surface, {}}).triangleCount());
}

void BM_ParseAndReplay(benchmark::State& state) {
  const std::string text = asText(sixtySecondsOfDragging());
  for (auto _ : state) {
    std::istringstream in(text);
    const ReplayResult result = replayRecording(parseRecording(in, "benchmark"));
    benchmark::DoNotOptimize(result.sheet.positions.data());
  }
  state.counters["bytes"] = static_cast<double>(text.size());
}

BENCHMARK(BM_Replay)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseAndReplay)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
