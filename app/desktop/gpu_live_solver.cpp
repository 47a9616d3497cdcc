#include "app/desktop/gpu_live_solver.hpp"

#include <vector>

#include "engine/simulation_vk/gpu_dynamic_solver.hpp"

namespace curvefold::desktop {

namespace {

class GpuLiveSolver final : public LiveSolver {
 public:
  GpuLiveSolver(const VulkanContext& context, const BarHingeModel& model,
                const SimulationState& flat)
      : solver_(context, model) {
    solver_.setState(flat);
  }

  void advance(const BarHingeModel&, double, double amount, std::uint32_t steps,
               const std::optional<LivePull>& pull, SimulationState& state) override {
    std::optional<GpuPull> devicePull;
    if (pull) devicePull = GpuPull{pull->vertex, pull->to, pull->impulse};
    solver_.step(amount, steps, devicePull);
    solver_.positions(state.positions);
    state.steps = solver_.steps();
  }

  void setState(const SimulationState& state) override { solver_.setState(state); }

 private:
  GpuDynamicSolver solver_;
};

}  // namespace

bool supportsLiveCompute(const VulkanContext& context) {
  std::uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &familyCount, families.data());
  return context.graphicsFamily() < familyCount &&
         (families[context.graphicsFamily()].queueFlags & VK_QUEUE_COMPUTE_BIT) != 0;
}

LiveSolverFactory gpuLiveSolver(const VulkanContext& context) {
  return [&context](const BarHingeModel& model, const SimulationState& flat) {
    return std::unique_ptr<LiveSolver>(std::make_unique<GpuLiveSolver>(context, model, flat));
  };
}

}  // namespace curvefold::desktop
