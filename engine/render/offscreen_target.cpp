#include "engine/render/offscreen_target.hpp"

#include <cstring>

namespace curvefold {

OffscreenTarget::OffscreenTarget(const VulkanContext& context, VkExtent2D extent,
                                 VkSampleCountFlagBits samples, std::uint32_t framesInFlight,
                                 VkFormat color)
    : context_(context), extent_(extent) {
  if (color != VK_FORMAT_R8G8B8A8_UNORM && color != VK_FORMAT_R8G8B8A8_SRGB)
    throw VulkanError("an offscreen target is R8G8B8A8, UNORM or SRGB");
  if (extent.width == 0 || extent.height == 0) throw VulkanError("render size must not be zero");
  const auto& limits = context.properties().limits;
  if (extent.width > limits.maxFramebufferWidth || extent.height > limits.maxFramebufferHeight)
    throw VulkanError("render size " + std::to_string(extent.width) + "x" +
                      std::to_string(extent.height) + " exceeds the device's limit of " +
                      std::to_string(limits.maxFramebufferWidth) + "x" +
                      std::to_string(limits.maxFramebufferHeight));
  format_.color = color;
  format_.depth = chooseDepthFormat(context);
  format_.samples = context.sampleCountUpTo(samples);
  format_.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  const VkDevice device = context.device();
  try {
    renderPass_ = createScenePass(device, format_);
    TransientAttachments transient = createTransientAttachments(context, extent, format_);
    multisampled_ = std::move(transient.multisampled);
    depth_ = std::move(transient.depth);
    resolved_ = GpuImage(context, extent, format_.color, VK_SAMPLE_COUNT_1_BIT,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                         VK_IMAGE_ASPECT_COLOR_BIT);
    framebuffer_ = createSceneFramebuffer(device, renderPass_, format_, extent, resolved_.view(),
                                          depth_.view(), multisampled_.view());
    const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
    for (std::uint32_t i = 0; i < framesInFlight; ++i)
      readbacks_.emplace_back(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  } catch (...) {
    if (framebuffer_) vkDestroyFramebuffer(device, framebuffer_, nullptr);
    if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
    throw;
  }
}

OffscreenTarget::~OffscreenTarget() {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  vkDestroyFramebuffer(device, framebuffer_, nullptr);
  vkDestroyRenderPass(device, renderPass_, nullptr);
}

void OffscreenTarget::recordAfterPass(Frame& frame) {
  if (!readbackEnabled_) return;
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyImageToBuffer(frame.commands, resolved_.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         readbacks_[frame.slot].buffer(), 1, &region);
  // The host reads the buffer after the fence.
  VkBufferMemoryBarrier barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.buffer = readbacks_[frame.slot].buffer();
  barrier.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(frame.commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                       0, 0, nullptr, 1, &barrier, 0, nullptr);
}

RgbaImage OffscreenTarget::readback(const Frame& frame) const {
  RgbaImage image;
  image.width = extent_.width;
  image.height = extent_.height;
  image.pixels.resize(std::size_t(image.width) * image.height * 4);
  std::memcpy(image.pixels.data(), readbacks_[frame.slot].data(), image.pixels.size());
  return image;
}

}  // namespace curvefold
