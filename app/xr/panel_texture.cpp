#include "app/xr/panel_texture.hpp"

#include <imgui.h>
#include <imgui_impl_vulkan.h>

#include "app/studio/imgui_context_scope.hpp"
#include "engine/render/frames.hpp"
#include "engine/render/scope_fail.hpp"
#include "engine/render/vulkan_error.hpp"
#include "engine/render/vulkan_objects.hpp"

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
  const ScopeFail cleanup([this] { destroy(); });
  image_ = GpuImage(context, extent, VK_FORMAT_R8G8B8A8_UNORM, VK_SAMPLE_COUNT_1_BIT,
                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                    VK_IMAGE_ASPECT_COLOR_BIT);

  // Cleared: the last picture is not needed.
  const VkAttachmentDescription color = describeAttachment(
      VK_FORMAT_R8G8B8A8_UNORM, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR,
      VK_ATTACHMENT_STORE_OP_STORE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &reference;
  const VkSubpassDependency dependencies[2] = {
      // The eyes of earlier frames sampled it: their reads finish before it is drawn again.
      subpassDependency(VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT),
      // This frame's eyes sample it after it is drawn.
      subpassDependency(0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_SUBPASS_EXTERNAL,
                        VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT)};
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

  sampler_ = createSampler(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);

  // The font atlas's descriptor set.
  pool_ = createDescriptorPool(device, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                               VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT);

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
  destroyHandle(device, pool_, vkDestroyDescriptorPool);
  destroyHandle(device, sampler_, vkDestroySampler);
  destroyHandle(device, framebuffer_, vkDestroyFramebuffer);
  destroyHandle(device, renderPass_, vkDestroyRenderPass);
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
