#include "engine/render/render_target.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/render/vulkan_objects.hpp"

namespace curvefold {

bool isSrgbFormat(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
    case VK_FORMAT_R8G8B8_SRGB:
    case VK_FORMAT_B8G8R8_SRGB:
      return true;
    default:
      return false;
  }
}

glm::vec4 targetColor(const glm::vec4& srgbEncoded, const PassFormat& format) {
  if (!isSrgbFormat(format.color)) return srgbEncoded;
  // The sRGB transfer function's inverse, as shaders/target_color.glsl applies it.
  auto linear = [](float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  };
  return {linear(srgbEncoded.r), linear(srgbEncoded.g), linear(srgbEncoded.b), srgbEncoded.a};
}

TransientAttachments createTransientAttachments(const VulkanContext& context, VkExtent2D extent,
                                                const PassFormat& format) {
  TransientAttachments result;
  if (format.samples != VK_SAMPLE_COUNT_1_BIT)
    result.multisampled =
        GpuImage(context, extent, format.color, format.samples,
                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                 VK_IMAGE_ASPECT_COLOR_BIT, format.views);
  const VkImageAspectFlags depthAspect =
      format.depth == VK_FORMAT_D24_UNORM_S8_UINT
          ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT
          : VK_IMAGE_ASPECT_DEPTH_BIT;
  result.depth = GpuImage(
      context, extent, format.depth, format.samples,
      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
      depthAspect, format.views);
  return result;
}

VkRenderPass createScenePass(VkDevice device, const PassFormat& format) {
  const bool msaa = format.samples != VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkAttachmentDescription> attachments = {
      // With MSAA only the resolved image is kept.
      describeAttachment(format.color, format.samples, VK_ATTACHMENT_LOAD_OP_CLEAR,
                         msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE,
                         msaa ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : format.finalLayout),
      describeAttachment(format.depth, format.samples, VK_ATTACHMENT_LOAD_OP_CLEAR,
                         VK_ATTACHMENT_STORE_OP_DONT_CARE,
                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL)};
  if (msaa)
    attachments.push_back(describeAttachment(format.color, VK_SAMPLE_COUNT_1_BIT,
                                             VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                             VK_ATTACHMENT_STORE_OP_STORE, format.finalLayout));
  VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkAttachmentReference resolveRef{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colorRef;
  subpass.pResolveAttachments = msaa ? &resolveRef : nullptr;
  subpass.pDepthStencilAttachment = &depthRef;

  // The previous frame's use of the same images (drawing, the readback copy or presentation)
  // finishes before this frame writes them; the copy after the pass sees the resolved colour.
  const VkSubpassDependency dependencies[2] = {
      subpassDependency(
          VK_SUBPASS_EXTERNAL,
          VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
              VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, 0,
          VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
              VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
          VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT),
      subpassDependency(0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_SUBPASS_EXTERNAL,
                        VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT)};

  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = dependencies;
  // Multiview: every view drawn by each draw, into its own layer; the views are correlated (the
  // eyes see nearly the same), which lets an implementation share work between them.
  const std::uint32_t viewMask = (1u << format.views) - 1u;
  VkRenderPassMultiviewCreateInfo multiview{VK_STRUCTURE_TYPE_RENDER_PASS_MULTIVIEW_CREATE_INFO};
  multiview.subpassCount = 1;
  multiview.pViewMasks = &viewMask;
  multiview.correlationMaskCount = 1;
  multiview.pCorrelationMasks = &viewMask;
  if (format.views > 1) info.pNext = &multiview;
  VkRenderPass pass = VK_NULL_HANDLE;
  vkCheck(vkCreateRenderPass(device, &info, nullptr, &pass), "vkCreateRenderPass");
  return pass;
}

VkFramebuffer createSceneFramebuffer(VkDevice device, VkRenderPass pass, const PassFormat& format,
                                     VkExtent2D extent, VkImageView image, VkImageView depth,
                                     VkImageView multisampled) {
  std::vector<VkImageView> attachments;
  if (format.samples != VK_SAMPLE_COUNT_1_BIT)
    attachments = {multisampled, depth, image};
  else
    attachments = {image, depth};
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = pass;
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.width = extent.width;
  info.height = extent.height;
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  vkCheck(vkCreateFramebuffer(device, &info, nullptr, &framebuffer), "vkCreateFramebuffer");
  return framebuffer;
}

VkFormat chooseDepthFormat(const VulkanContext& context) {
  for (VkFormat format : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D16_UNORM}) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &properties);
    if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)
      return format;
  }
  throw VulkanError("no depth attachment format on " + context.deviceName());
}

}  // namespace curvefold
