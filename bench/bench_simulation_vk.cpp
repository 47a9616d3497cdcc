// The folding simulation's Vulkan compute path (engine/simulation_vk) against the CPU path in the
// same run: one damped dynamic step at 10k and 100k vertices (and 1M, for a GPU), the same
// patterns as bench_simulation (a square grid with one crease through the middle). The GPU step
// is timed from submission to the fence, one step per submission (a live frame's worst case)
// and ten per submission (the cost of a step where a frame takes several). Runs on the device
// the loader picks (lavapipe without a GPU; CURVEFOLD_VK_DEVICE=substring picks another).
#include <benchmark/benchmark.h>

#include "bench/simulation_bench_support.hpp"
#include "engine/render/vulkan_context.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation_vk/gpu_dynamic_solver.hpp"

namespace curvefold {
namespace {

const VulkanContext& context() {
  static const VulkanContext instance{ContextOptions{}};
  return instance;
}

void BM_CpuDynamicStep(benchmark::State& bench) {
  simbench::timeCpuDynamicStep(bench);
}

void gpuSteps(benchmark::State& bench, std::size_t stepsPerSubmit) {
  const BarHingeModel model = simbench::creasedGrid(bench);
  GpuDynamicSolver solver(context(), model);
  solver.step(0.5, 10);
  for (auto _ : bench) solver.step(0.5, stepsPerSubmit);
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * stepsPerSubmit));
  bench.counters["vertices"] = static_cast<double>(model.vertexCount());
  bench.SetLabel(context().deviceName());
}
void BM_GpuDynamicStep(benchmark::State& bench) {
  gpuSteps(bench, 1);
}
void BM_GpuDynamicTenSteps(benchmark::State& bench) {
  gpuSteps(bench, 10);
}

// 100 x 100 cells: 10,201 vertices; 316 x 316: 100,489; 1000 x 1000: 1,002,001 (for a GPU:
// --benchmark_filter='/1000').
BENCHMARK(BM_CpuDynamicStep)
    ->Arg(100)
    ->Arg(316)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_GpuDynamicStep)
    ->Arg(100)
    ->Arg(316)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_GpuDynamicTenSteps)
    ->Arg(100)
    ->Arg(316)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
