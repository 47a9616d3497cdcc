#include "engine/render/image_barrier.hpp"

namespace curvefold {

void imageBarrier(VkCommandBuffer commands, VkImage image, VkImageAspectFlags aspect,
                  const ImageUse& from, const ImageUse& to, std::uint32_t layers,
                  std::uint32_t firstLayer) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = from.access;
  barrier.dstAccessMask = to.access;
  barrier.oldLayout = from.layout;
  barrier.newLayout = to.layout;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {aspect, 0, 1, firstLayer, layers};
  vkCmdPipelineBarrier(commands, from.stage, to.stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace curvefold
