// The live simulation's Vulkan compute solver (issue 39, 4): interaction/live_simulation.hpp's
// LiveSolver over engine/simulation_vk's GpuDynamicSolver (Origami Simulator's GPU step: Ghassaei,
// Demaine & Gershenfeld, 7OSME 2018), for the window and the headset on their own device.
//
// Input: the host's Vulkan context, which must outlive every solver made. Each frame the state
// stays on the device; only the positions come back (the state's velocities and hinge angles
// stay those of the flat start). Float: bit for bit on one device, not across devices, so a
// recording of a GPU run is not replayed (sim_input/player.hpp).
//
// Known limits: runs on the context's graphics queue and waits for it, so it must step on the
// thread that draws (LiveSimulation's onWorker off); a device whose graphics queue cannot run
// compute is refused (supportsLiveCompute false; the factory throws VulkanError).
#pragma once

#include "engine/render/vulkan_context.hpp"
#include "interaction/live_simulation.hpp"

namespace curvefold::desktop {

// Whether the context's graphics queue runs compute shaders (every Vulkan GPU and lavapipe).
bool supportsLiveCompute(const VulkanContext& context);

// Makes GPU solvers on `context` (a reference is kept).
LiveSolverFactory gpuLiveSolver(const VulkanContext& context);

}  // namespace curvefold::desktop
