// Vulkan failures as exceptions with one-line messages ("vkCreateDevice failed: VK_ERROR_...").
#pragma once

#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace curvefold {

// No usable Vulkan driver or device, or a Vulkan call that failed.
class VulkanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

const char* vkResultName(VkResult result);

inline void vkCheck(VkResult result, const char* what) {
  if (result != VK_SUCCESS)
    throw VulkanError(std::string(what) + " failed: " + vkResultName(result));
}

}  // namespace curvefold
