// Replay of a 60 s, 90 Hz recording of continuous two-handed dragging on a 20k-triangle sheet,
// without rendering (docs/design.md 8: < 1 s), with and without parsing the JSON Lines text.
//
//   build/bench/bench_replay --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <cmath>
#include <numbers>
#include <sstream>

#include <benchmark/benchmark.h>

#include "bench/dragging_session.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {
namespace {

// ~20k triangles (bench/dragging_session.hpp).
const Recording& dragging20k() {
  static const Recording recording = sixtySecondsOfDragging(116);
  return recording;
}

std::string asText(const Recording& recording) {
  std::string text = headerLine(recording.header) + "\n";
  for (const InputFrame& frame : recording.frames) text += frameLine(frame) + "\n";
  return text;
}

void BM_Replay(benchmark::State& state) {
  const Recording& recording = dragging20k();
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
  const std::string text = asText(dragging20k());
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
