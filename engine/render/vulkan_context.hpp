// The Vulkan instance, physical device, logical device and graphics queue, made by small builders
// in the style of vk-bootstrap (written here). Works on Mesa's lavapipe (a CPU device) and on any
// GPU: devices are ranked discrete > integrated > virtual > CPU, and CURVEFOLD_VK_DEVICE=substring
// picks one by name.
//
// With validation on, VK_LAYER_KHRONOS_validation is enabled and a debug messenger collects every
// warning and error it reports, so tests can fail on any message (validationMessageCount()).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/render/vulkan_error.hpp"

namespace curvefold {

// Warnings and errors from the validation layer, counted as they arrive (any thread).
struct ValidationLog {
  std::atomic<std::size_t> count{0};
  std::mutex mutex;
  std::vector<std::string> messages;  // the first few hundred, for test failure output
};

struct InstanceOptions {
  std::string applicationName = "curvefold";
  bool validation = false;              // throws VulkanError when the layer is missing
  std::vector<std::string> extensions;  // e.g. glfwGetRequiredInstanceExtensions()
  // Creates the instance from the create info when given (OpenXR's xrCreateVulkanInstanceKHR,
  // which adds what the runtime needs); vkCreateInstance otherwise. Throws on failure.
  std::function<VkInstance(const VkInstanceCreateInfo&)> createInstance;
};

// Creates the instance (and the debug messenger when validating). Throws VulkanError when no
// Vulkan driver is installed.
class InstanceBuilder {
 public:
  explicit InstanceBuilder(InstanceOptions options) : options_(std::move(options)) {}
  struct Result {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    std::shared_ptr<ValidationLog> log;  // null without validation
  };
  Result build() const;

 private:
  InstanceOptions options_;
};

struct DeviceRequirements {
  std::vector<std::string> extensions;           // e.g. VK_KHR_swapchain for a window
  VkSurfaceKHR presentSurface = VK_NULL_HANDLE;  // the graphics queue must present to it
  VkPhysicalDevice required = VK_NULL_HANDLE;    // the only candidate (an XR runtime's device)
};

struct PhysicalDeviceChoice {
  VkPhysicalDevice device = VK_NULL_HANDLE;
  std::uint32_t graphicsFamily = 0;
  VkPhysicalDeviceProperties properties{};
};

// Picks the best suitable device: Vulkan 1.1, a graphics queue (that can present, when asked) and
// the extensions asked for.
// CURVEFOLD_VK_DEVICE=substring (case-insensitive) restricts the choice to devices whose name
// contains it. Throws VulkanError naming the devices seen when none fits.
PhysicalDeviceChoice selectPhysicalDevice(VkInstance instance, const DeviceRequirements& needs);

struct ContextOptions {
  InstanceOptions instance;
  DeviceRequirements device;  // presentSurface is filled from createSurface when given
  // For a window: creates the surface from the instance (e.g. glfwCreateWindowSurface); the
  // context owns and destroys it.
  std::function<VkSurfaceKHR(VkInstance)> createSurface;
  // For OpenXR (XR_KHR_vulkan_enable2): the device the runtime renders with, and the runtime's
  // xrCreateVulkanDeviceKHR in place of vkCreateDevice. Both throw on failure.
  std::function<VkPhysicalDevice(VkInstance)> requiredPhysicalDevice;
  std::function<VkDevice(VkPhysicalDevice, const VkDeviceCreateInfo&)> createDevice;
};

// Owns the instance, optional surface, device and graphics queue. Not copyable or movable.
class VulkanContext {
 public:
  explicit VulkanContext(const ContextOptions& options = {});
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return choice_.device; }
  VkDevice device() const { return device_; }
  VkQueue graphicsQueue() const { return queue_; }
  std::uint32_t graphicsFamily() const { return choice_.graphicsFamily; }
  VkSurfaceKHR surface() const { return surface_; }
  const VkPhysicalDeviceProperties& properties() const { return choice_.properties; }
  std::string deviceName() const { return choice_.properties.deviceName; }

  // A driver that rasterizes on the CPU (lavapipe).
  bool cpuDevice() const { return choice_.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  // The device draws several views in one pass (VK_KHR_multiview's feature, enabled when there).
  bool multiview() const { return multiview_; }
  // Largest sample count usable for both colour and depth framebuffers, at most `wanted`.
  VkSampleCountFlagBits sampleCountUpTo(VkSampleCountFlagBits wanted) const;
  // The sample count for interactive views (window, headset): 4x MSAA on a GPU, none on a CPU
  // device, where 4x costs lavapipe about 20 ms a frame at 1280x720 (README, Performance).
  VkSampleCountFlagBits interactiveSampleCount() const;
  // A memory type among typeBits with all the flags; throws VulkanError when there is none.
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags flags) const;
  // Prefers `preferred`, falls back to any type in typeBits.
  std::uint32_t memoryTypePreferring(std::uint32_t typeBits, VkMemoryPropertyFlags preferred) const;

  bool validationEnabled() const { return log_ != nullptr; }
  std::size_t validationMessageCount() const { return log_ ? log_->count.load() : 0; }
  std::vector<std::string> validationMessages() const;

  void waitIdle() const;

 private:
  void destroyInstance();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  std::shared_ptr<ValidationLog> log_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  PhysicalDeviceChoice choice_;
  VkPhysicalDeviceMemoryProperties memory_{};
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  bool multiview_ = false;
};

}  // namespace curvefold
