#include "engine/render/vulkan_objects.hpp"

#include "engine/render/vulkan_error.hpp"

namespace curvefold {

VkImageView createImageView(VkDevice device, VkImage image, VkFormat format,
                            VkImageAspectFlags aspect, std::uint32_t layers) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image;
  info.viewType = layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  info.format = format;
  info.subresourceRange = {aspect, 0, 1, 0, layers};
  VkImageView view = VK_NULL_HANDLE;
  vkCheck(vkCreateImageView(device, &info, nullptr, &view), "vkCreateImageView");
  return view;
}

VkAttachmentDescription describeAttachment(VkFormat format, VkSampleCountFlagBits samples,
                                           VkAttachmentLoadOp load, VkAttachmentStoreOp store,
                                           VkImageLayout finalLayout) {
  // flags, format, samples, load and store, the stencil's load and store, initial and final layout
  return {0,
          format,
          samples,
          load,
          store,
          VK_ATTACHMENT_LOAD_OP_DONT_CARE,
          VK_ATTACHMENT_STORE_OP_DONT_CARE,
          VK_IMAGE_LAYOUT_UNDEFINED,
          finalLayout};
}

VkSubpassDependency subpassDependency(std::uint32_t src, VkPipelineStageFlags srcStages,
                                      VkAccessFlags srcAccess, std::uint32_t dst,
                                      VkPipelineStageFlags dstStages, VkAccessFlags dstAccess) {
  return {src, dst, srcStages, dstStages, srcAccess, dstAccess, 0};
}

VkSampler createSampler(VkDevice device, VkFilter filter, VkSamplerAddressMode address) {
  const VkSamplerCreateInfo info{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                 .magFilter = filter,
                                 .minFilter = filter,
                                 .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                 .addressModeU = address,
                                 .addressModeV = address,
                                 .addressModeW = address};
  VkSampler sampler = VK_NULL_HANDLE;
  vkCheck(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler");
  return sampler;
}

VkDescriptorPool createDescriptorPool(VkDevice device, VkDescriptorType type, std::uint32_t sets,
                                      VkDescriptorPoolCreateFlags flags) {
  const VkDescriptorPoolSize size{type, sets};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.flags = flags;
  info.maxSets = sets;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  vkCheck(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
  return pool;
}

VkDescriptorSet allocateDescriptorSet(VkDevice device, VkDescriptorPool pool,
                                      VkDescriptorSetLayout layout) {
  VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  info.descriptorPool = pool;
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  vkCheck(vkAllocateDescriptorSets(device, &info, &set), "vkAllocateDescriptorSets");
  return set;
}

}  // namespace curvefold
