// The damped dynamic solver of the bar-and-hinge model (engine/simulation/dynamic_solver.hpp) as
// Vulkan compute shaders, the way Origami Simulator runs it on the GPU (Ghassaei, Demaine &
// Gershenfeld, "Fast, Interactive Origami Simulation using GPU Computation", 7OSME 2018): the same
// model, the same force slots and gather lists, the same step. Per step two kernels: every
// element's forces into its own slots (shaders/simulation_elements.comp), then every vertex sums
// its slots in the gather list's order and moves (shaders/simulation_vertices.comp). The state
// stays on the device between calls; setState / state copy it in and out.
//
// Single precision (the CPU path is double): a GPU's double rate is 1/2 to 1/64 of its float rate
// and Origami Simulator runs in float too. Float rounds a 0.2 m sheet's positions to about 1e-8 m,
// so the two paths agree to a tolerance (tests/test_simulation_vk.cpp states it), not bit for bit.
// Bar rest lengths are measured on the device from the flat positions by the expression the
// step uses, so the flat state at fold amount 0 stays exactly flat.
//
// Deterministic on one device: the same model, fold amount, state and step count give the same
// state bit for bit (no atomics; each slot and vertex is written by one invocation in a fixed
// order).
//
// Known limits: needs a queue family with graphics and compute (every Vulkan GPU and lavapipe has
// one; VulkanError otherwise); runs on the context's graphics queue, so the caller must not submit
// to it from another thread meanwhile. Each call waits for the device (no overlap with drawing).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/render/gpu_resources.hpp"
#include "engine/render/vulkan_context.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/dynamic_solver.hpp"

namespace curvefold {

// One vertex pulled toward a point (the model's frame) by a spring, as the live simulation pulls
// (interaction/live_simulation.hpp): before each step its velocity gains impulse (to - x).
struct GpuPull {
  std::uint32_t vertex = 0;
  glm::dvec3 to{0.0};
  double impulse = 0.0;  // dt k / m, per metre
};

class GpuDynamicSolver {
 public:
  // Uploads the model (its stiffnesses, targets and gather lists, as float) and its flat state.
  // The model may go; the context must outlive the solver. Throws VulkanError.
  GpuDynamicSolver(const VulkanContext& context, const BarHingeModel& model,
                   const DynamicOptions& options = {});
  ~GpuDynamicSolver();
  GpuDynamicSolver(const GpuDynamicSolver&) = delete;
  GpuDynamicSolver& operator=(const GpuDynamicSolver&) = delete;

  // Replaces the device's state: positions, velocities (zero when empty), hinge angles
  // (measured from the positions when their count is not the hinges'), and the step count.
  void setState(const SimulationState& state);
  // Advances the device's state by `steps` fixed steps toward the fold amount (0..1), with the
  // pull, if any, before each step (none on a pinned vertex).
  void step(double foldAmount, std::size_t steps, const std::optional<GpuPull>& pull = {});
  // Copies the device's state into `state` (positions, velocities, hinge angles, steps).
  void state(SimulationState& state);
  // Only the positions (what a frame draws).
  void positions(std::vector<glm::dvec3>& positions);
  std::size_t steps() const { return steps_; }
  std::size_t vertexCount() const { return vertexCount_; }

 private:
  template <typename Record>
  void submitAndWait(const Record& record);
  void upload(VkBuffer buffer, const void* data, VkDeviceSize bytes);
  void download(VkBuffer buffer, void* data, VkDeviceSize bytes);
  void dispatch(VkCommandBuffer commands, VkPipeline pipeline, std::size_t count) const;
  void destroy();

  const VulkanContext& context_;
  DynamicOptions options_;
  double timeStep_ = 0.0;
  std::uint32_t barCount_ = 0, hingeCount_ = 0, glueCount_ = 0, vertexCount_ = 0;
  float glueStiffness_ = 0.0f;
  std::size_t steps_ = 0;
  std::vector<DeviceBuffer> buffers_;  // by binding (simulation_layout.glsl)
  HostBuffer staging_;                 // uploads and downloads, grown as needed
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
  VkPipeline elements_ = VK_NULL_HANDLE, vertices_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  VkDescriptorSet descriptorSet_ = VK_NULL_HANDLE;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence done_ = VK_NULL_HANDLE;
  std::vector<Hinge> hinges_;         // to measure angles when a state comes without them
  std::vector<std::uint8_t> pinned_;  // a pull on a pinned vertex is none
};

}  // namespace curvefold
