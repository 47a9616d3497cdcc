// The simulated runtime's side of XR_KHR_vulkan_enable2: swapchain images made on the
// application's device, handed over in the attachment layout the extension promises, and read
// back to PNG (the runtime's "display").
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace curvefold::simxr {

struct VulkanBinding {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  std::uint32_t queueIndex = 0;
};

class SwapchainImages {
 public:
  // layers: the swapchain's arraySize (one layer per view for a multiview app).
  SwapchainImages(const VulkanBinding& binding, VkFormat format, std::uint32_t width,
                  std::uint32_t height, VkImageUsageFlags usage, std::uint32_t count,
                  std::uint32_t layers = 1);
  ~SwapchainImages();
  SwapchainImages(const SwapchainImages&) = delete;
  SwapchainImages& operator=(const SwapchainImages&) = delete;

  const std::vector<VkImage>& images() const { return images_; }
  bool depth() const { return depth_; }
  std::uint32_t layers() const { return layers_; }
  // Copies a layer of an image (in its attachment layout) to host memory and writes it as a PNG.
  void savePng(std::uint32_t index, std::uint32_t layer, const std::filesystem::path& path) const;

 private:
  void release();
  template <typename Record>
  void submitOnce(Record record) const;

  VulkanBinding binding_;
  VkFormat format_;
  std::uint32_t width_, height_;
  std::uint32_t layers_;
  bool depth_;
  std::vector<VkImage> images_;
  std::vector<VkDeviceMemory> memory_;
};

// Vulkan formats the runtime offers for swapchains on this device (colour, then depth).
// The format's Vulkan name without "VK_FORMAT_" ("R8G8B8A8_SRGB"), for the log.
std::string swapchainFormatName(std::int64_t format);
std::vector<std::int64_t> swapchainFormats(VkPhysicalDevice device);

}  // namespace curvefold::simxr
