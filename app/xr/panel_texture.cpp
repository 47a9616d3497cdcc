#include "app/xr/panel_texture.hpp"

#include <imgui.h>
#include <imgui_impl_vulkan.h>

#include "app/imgui_context_scope.hpp"
#include "engine/render/frames.hpp"
#include "engine/render/vulkan_error.hpp"

namespace curvefold::xr {

namespace {

void checkImGuiVulkan(VkResult result) {
  if (result != VK_SUCCESS) vkCheck(result, "Dear ImGui's Vulkan backend");
}

}  // namespace

PanelTexture::PanelTexture(const VulkanContext& context, ImGuiContext* imgui, VkExtent2D extent,
                           std::uint32_t framesInFlight)
    : context_(context), imgui_(imgui), extent_(extent) {
  const VkDevice device = context.device();
  try {
    image_ = GpuImage(context, extent, VK_FORMAT_R8G8B8A8_UNORM, VK_SAMPLE_COUNT_1_BIT,
                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                      VK_IMAGE_ASPECT_COLOR_BIT);

    VkAttachmentDescription color{};
    color.format = VK_FORMAT_R8G8B8A8_UNORM;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // cleared: the last picture is not needed
    color.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &reference;
    VkSubpassDependency dependencies[2]{};
    // The eyes of earlier frames sampled it: their reads finish before it is drawn again.
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[0].srcAccessMask = 0;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    // This frame's eyes sample it after it is drawn.
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    passInfo.attachmentCount = 1;
    passInfo.pAttachments = &color;
    passInfo.subpassCount = 1;
    passInfo.pSubpasses = &subpass;
    passInfo.dependencyCount = 2;
    passInfo.pDependencies = dependencies;
    vkCheck(vkCreateRenderPass(device, &passInfo, nullptr, &renderPass_), "vkCreateRenderPass");

    const VkImageView view = image_.view();
    VkFramebufferCreateInfo framebufferInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    framebufferInfo.renderPass = renderPass_;
    framebufferInfo.attachmentCount = 1;
    framebufferInfo.pAttachments = &view;
    framebufferInfo.width = extent.width;
    framebufferInfo.height = extent.height;
    framebufferInfo.layers = 1;
    vkCheck(vkCreateFramebuffer(device, &framebufferInfo, nullptr, &framebuffer_),
            "vkCreateFramebuffer");

    VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    samplerInfo.magFilter = VK_FILTER_LINEAR;
    samplerInfo.minFilter = VK_FILTER_LINEAR;
    samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    vkCheck(vkCreateSampler(device, &samplerInfo, nullptr, &sampler_), "vkCreateSampler");

    // The font atlas's descriptor set.
    VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &poolSize;
    vkCheck(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");

    studio::ImGuiContextScope scope(imgui_);
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance();
    info.PhysicalDevice = context.physicalDevice();
    info.Device = device;
    info.QueueFamily = context.graphicsFamily();
    info.Queue = context.graphicsQueue();
    info.DescriptorPool = pool_;
    // ImGui rewrites a frame's vertex buffers ImageCount draws later: one more than can be in
    // flight, so it never rewrites one the GPU still reads.
    info.MinImageCount = framesInFlight + 1;
    info.ImageCount = framesInFlight + 1;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkImGuiVulkan;
    if (!ImGui_ImplVulkan_Init(&info, renderPass_))
      throw VulkanError("Dear ImGui's Vulkan backend did not start");
    backend_ = true;
    FrameRing upload(context, 1);
    Frame& frame = upload.begin();
    ImGui_ImplVulkan_CreateFontsTexture(frame.commands);
    upload.submit(frame);
    upload.wait(frame);
    ImGui_ImplVulkan_DestroyFontUploadObjects();
  } catch (...) {
    destroy();
    throw;
  }
}

PanelTexture::~PanelTexture() {
  destroy();
}

void PanelTexture::destroy() {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  if (backend_) {
    studio::ImGuiContextScope scope(imgui_);
    ImGui_ImplVulkan_Shutdown();
    backend_ = false;
  }
  if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
  if (sampler_) vkDestroySampler(device, sampler_, nullptr);
  if (framebuffer_) vkDestroyFramebuffer(device, framebuffer_, nullptr);
  if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
  pool_ = VK_NULL_HANDLE;
  sampler_ = VK_NULL_HANDLE;
  framebuffer_ = VK_NULL_HANDLE;
  renderPass_ = VK_NULL_HANDLE;
  image_.reset();
}

void PanelTexture::record(VkCommandBuffer commands, ImDrawData* drawData) {
  VkClearValue clear{};
  clear.color = {{0.12f, 0.12f, 0.14f, 1.0f}};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffer_;
  begin.renderArea = {{0, 0}, extent_};
  begin.clearValueCount = 1;
  begin.pClearValues = &clear;
  vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  if (drawData) {
    studio::ImGuiContextScope scope(imgui_);
    ImGui_ImplVulkan_RenderDrawData(drawData, commands);
  }
  vkCmdEndRenderPass(commands);
}

}  // namespace curvefold::xr
