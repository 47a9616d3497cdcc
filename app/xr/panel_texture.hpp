// The headset panel's picture: the studio's Dear ImGui draw data rendered into a texture (its own
// colour image, render pass and framebuffer, through ImGui's Vulkan backend in the studio's ImGui
// context) before the eyes are drawn, and sampled by the scene renderer on the quad the
// non-dominant hand holds (Scene::worldPanel).
#pragma once

#include <vulkan/vulkan.h>

#include "engine/render/gpu_resources.hpp"
#include "engine/render/vulkan_context.hpp"

struct ImGuiContext;
struct ImDrawData;

namespace curvefold::xr {

class PanelTexture {
 public:
  // Uploads the context's font atlas (waits for it). framesInFlight: how many of the host's
  // frames may be on the GPU at once (ImGui keeps vertex buffers per frame). Throws VulkanError.
  PanelTexture(const VulkanContext& context, ImGuiContext* imgui, VkExtent2D extent,
               std::uint32_t framesInFlight);
  ~PanelTexture();
  PanelTexture(const PanelTexture&) = delete;
  PanelTexture& operator=(const PanelTexture&) = delete;

  // Outside any render pass: clears the picture and draws `drawData` into it, leaving it ready to
  // sample (SHADER_READ_ONLY_OPTIMAL). Reads of the last picture by earlier submissions on the
  // same queue finish first (the render pass's external dependency).
  void record(VkCommandBuffer commands, ImDrawData* drawData);

  VkImageView view() const { return image_.view(); }
  VkSampler sampler() const { return sampler_; }
  VkExtent2D extent() const { return extent_; }

 private:
  void destroy();

  const VulkanContext& context_;
  ImGuiContext* imgui_;
  VkExtent2D extent_;
  GpuImage image_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  bool backend_ = false;
};

}  // namespace curvefold::xr
