// One image's layout transition and the dependency around it, in a line: where the image was used
// (its layout, the stage and the access), where it is used next, and which of its subresources.
// The repeated VkImageMemoryBarrier blocks become one call each.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

namespace curvefold {

struct ImageUse {
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
  VkAccessFlags access = 0;
};

// Records the transition of mip 0 of `layers` layers (from `firstLayer`) of `image`.
void imageBarrier(VkCommandBuffer commands, VkImage image, VkImageAspectFlags aspect,
                  const ImageUse& from, const ImageUse& to, std::uint32_t layers = 1,
                  std::uint32_t firstLayer = 0);

}  // namespace curvefold
