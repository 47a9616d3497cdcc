// Small makers and destroyers of the Vulkan objects several owners make alike (vulkan-guide's
// vkinit shape): each maker throws VulkanError, and the caller destroys what it returns.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

namespace curvefold {

// Destroys `handle` with its vkDestroy* (or vkFreeMemory) if it is set, and clears it: a destroy()
// that frees a half-made object, or runs twice, frees each handle once.
template <typename Handle>
void destroyHandle(VkDevice device, Handle& handle,
                   void (*destroy)(VkDevice, Handle, const VkAllocationCallbacks*)) {
  if (handle != VK_NULL_HANDLE) destroy(device, handle, nullptr);
  handle = VK_NULL_HANDLE;
}

// A view of mip 0 of `layers` layers of `image`: an array view where layers > 1 (a multiview
// pass's).
VkImageView createImageView(VkDevice device, VkImage image, VkFormat format,
                            VkImageAspectFlags aspect, std::uint32_t layers = 1);

// A render pass attachment without stencil whose old content is not kept (UNDEFINED on entry):
// `load` and `store` say what happens to its content, `finalLayout` where the pass leaves it.
VkAttachmentDescription describeAttachment(VkFormat format, VkSampleCountFlagBits samples,
                                           VkAttachmentLoadOp load, VkAttachmentStoreOp store,
                                           VkImageLayout finalLayout);

// What subpass `dst` waits for in subpass `src` (either may be VK_SUBPASS_EXTERNAL): src's
// stages and the writes they made, before dst's stages and accesses.
VkSubpassDependency subpassDependency(std::uint32_t src, VkPipelineStageFlags srcStages,
                                      VkAccessFlags srcAccess, std::uint32_t dst,
                                      VkPipelineStageFlags dstStages, VkAccessFlags dstAccess);

// A sampler of mip 0 with `filter` both ways and `address` on every axis.
VkSampler createSampler(VkDevice device, VkFilter filter, VkSamplerAddressMode address);

// A pool of `sets` descriptor sets of one descriptor of `type` each.
VkDescriptorPool createDescriptorPool(VkDevice device, VkDescriptorType type, std::uint32_t sets,
                                      VkDescriptorPoolCreateFlags flags = 0);

// One set of `layout` from `pool`.
VkDescriptorSet allocateDescriptorSet(VkDevice device, VkDescriptorPool pool,
                                      VkDescriptorSetLayout layout);

}  // namespace curvefold
