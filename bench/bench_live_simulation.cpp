// The live window's frame while simulating (issue 39, 4): on whatever Vulkan device the loader
// finds (lavapipe without a GPU), 1280x720 at 1 sample per pixel (the designer's CPU-device
// default), a cylinder design of about 10k vertices in design mode at 100%, each frame what the
// designer's loop does for the sheet: InteractionCore::process with the frame's simulation
// (liveStepsPerFrame dynamic steps and the rigid placement), the renderer told the sheet moved
// (InteractionSheetTracker), sceneForInteraction (the simulated sheet and its creases) and the
// frame drawn to its fence. Not counted: the ImGui panel's few hundred triangles and the
// swapchain's present. Second argument: 0 the whole frame, 1 the simulation alone (process, no
// drawing), 2 the drawing alone (process with 0 steps: the placement, the upload, the frame).
// Third argument: 1 steps the simulation on a worker while the frame draws (the designer's way,
// LiveSimulation's onWorker), 0 in turn. The CPU column is the whole process's (every thread:
// the solver's, lavapipe's), the frame's work whatever the machine's load. Fourth argument: 1
// steps on the Vulkan compute solver on the renderer's device (app/desktop/gpu_live_solver.hpp,
// the panel's "GPU"; in turn, as it must), 0 the CPU's.
// Counters: fps (frames per second of real time), vertices, steps per frame.
//
//   build/bench/bench_live_simulation --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <algorithm>
#include <cmath>
#include <memory>

#include <benchmark/benchmark.h>

#include "app/desktop/gpu_live_solver.hpp"
#include "app/desktop/interaction_scene.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/render/vulkan_context.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "interaction/interaction_core.hpp"

namespace curvefold {
namespace {

// The smallest even cylinder resolution with at least this many vertices: the count grows as the
// resolution squared, so start from that estimate and step by 2 (a 1M-vertex cylinder takes
// seconds to build; stepping up from 16 would take hundreds).
Sheet cylinderWithVertices(std::size_t vertices) {
  auto cylinder = [](int resolution) {
    return makeSurface("cylinder", {{"resolution", resolution}});
  };
  const double perSquare = double(cylinder(100).vertexCount()) / (100.0 * 100.0);
  int resolution = std::max(16, int(std::sqrt(double(vertices) / perSquare)) / 2 * 2);
  Sheet sheet = cylinder(resolution);
  while (sheet.vertexCount() < vertices) sheet = cylinder(resolution += 2);
  while (resolution > 16) {
    Sheet smaller = cylinder(resolution - 2);
    if (smaller.vertexCount() < vertices) break;
    sheet = std::move(smaller);
    resolution -= 2;
  }
  return sheet;
}

void BM_SimulatingWindowFrame(benchmark::State& state) {
  FoldSession session(cylinderWithVertices(std::size_t(state.range(0))));
  InteractionCore core(session, Pose{});
  core.setSimulationOnWorker(state.range(2) != 0);
  HeadlessOptions options;
  options.width = 1280;
  options.height = 720;
  options.samples = VK_SAMPLE_COUNT_1_BIT;
  HeadlessRenderer r(options);
  const bool gpu = state.range(3) != 0;
  if (gpu) core.setGpuSolver(desktop::gpuLiveSolver(r.context()));
  desktop::InteractionSheetTracker tracker;
  const Camera camera =
      frameBounds(worldBounds(session.initial()), ViewPreset::Iso, 1280.0f / 720.0f);
  const Ground ground = groundBelow(worldBounds(session.initial()));
  InputFrame input;
  const long part = state.range(1);
  auto frame = [&] {
    input.time += 1.0 / 60.0;
    input.simulation = liveSimulationInput(100.0, session.fixed());
    if (part == 2) input.simulation->steps = 0;
    if (gpu) input.simulation->solver = LiveSolverKind::Gpu;
    core.process(input);
    if (part == 1) return;
    tracker.update(core, r.sceneRenderer());
    Scene scene = desktop::sceneForInteraction(core, input, camera, ground);
    tracker.describe(core, scene.sheet);
    r.draw(scene);
  };
  frame();
  frame();
  if (!core.simulation()) {
    state.SkipWithError(core.simulationProblem().c_str());
    core.endSimulation();
    return;
  }
  for (auto _ : state) frame();
  core.endSimulation();  // a GPU solver goes before the renderer's device
  state.counters["fps"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["vertices"] = double(session.fixed().vertexCount());
  state.counters["steps_per_frame"] = double(liveStepsPerFrame(session.fixed().vertexCount()));
  state.SetLabel(r.context().deviceName());
}
BENCHMARK(BM_SimulatingWindowFrame)
    ->Args({10'000, 0, 0, 0})
    ->Args({10'000, 0, 1, 0})
    ->Args({10'000, 1, 0, 0})
    ->Args({10'000, 2, 0, 0})
    ->Args({10'000, 0, 0, 1})
    ->Args({10'000, 1, 0, 1})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->MinTime(3.0);

// For a GPU (issue 39: the compute path at 1M vertices at 90 Hz): a 1M-vertex cylinder stepped on
// the Vulkan solver; the whole frame, the simulation alone, the drawing alone. Skipped on a CPU
// device (lavapipe), where one such frame takes seconds.
void BM_MillionVertexGpuFrame(benchmark::State& state) {
  static const bool cpuDevice = [] {
    const VulkanContext context{ContextOptions{}};
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
    return properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  }();
  if (cpuDevice) {
    state.SkipWithError("the 1M-vertex frame is for a GPU; this device is a CPU (lavapipe)");
    return;
  }
  BM_SimulatingWindowFrame(state);
}
BENCHMARK(BM_MillionVertexGpuFrame)
    ->Args({1'000'000, 0, 0, 1})
    ->Args({1'000'000, 1, 0, 1})
    ->Args({1'000'000, 2, 0, 1})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->MinTime(3.0);

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
