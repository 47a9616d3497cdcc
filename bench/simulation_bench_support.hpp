// The set-up bench_simulation and bench_simulation_vk share: the creased grid they step (a
// square of cells x cells with one crease through the middle, folding to 90 degrees) and the CPU
// path's timed step, so the two programs time the very same CPU step.
#pragma once

#include <benchmark/benchmark.h>

#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "tests/simulation_test_support.hpp"

namespace curvefold::simbench {

// The grid of the benchmark's first argument in cells a side (100: 10,201 vertices; 316:
// 100,489; 1000: 1,002,001).
inline BarHingeModel creasedGrid(const benchmark::State& bench) {
  const int cells = static_cast<int>(bench.range(0));
  return buildModel(testing::creasedSquare(cells, cells / 2, 90.0, 0.2));
}

// One CPU dynamic step an iteration, on the grid folding toward 50% (ten steps in: not at rest).
inline void timeCpuDynamicStep(benchmark::State& bench) {
  const BarHingeModel model = creasedGrid(bench);
  SimulationState state = flatState(model);
  stepDynamic(model, 0.5, state, 10);
  for (auto _ : bench) {
    stepDynamic(model, 0.5, state, 1);
    benchmark::DoNotOptimize(state.positions.data());
  }
  bench.counters["vertices"] = static_cast<double>(model.vertexCount());
}

}  // namespace curvefold::simbench
