// Graphics pipelines for the scene renderer's passes: a shader module from embedded SPIR-V, and a
// builder whose fields are what the scene's pipelines differ in. Everything else is fixed: triangle
// lists, no culling (paper has two sides), dynamic viewport and scissor, depth test LESS_OR_EQUAL,
// and shaders/target_color.glsl's specialization constant for an sRGB target.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace curvefold {

// Throws VulkanError.
VkShaderModule createShaderModule(VkDevice device, std::span<const std::uint32_t> code);

// A small builder for the scene's graphics pipelines, which differ in shaders, vertex input, depth
// and blend (vk-bootstrap's and vulkan-guide's shape): fill the fields, then build().
struct PipelineBuilder {
  VkDevice device;
  VkPipelineLayout layout;
  VkRenderPass renderPass;
  VkSampleCountFlagBits samples;
  std::span<const std::uint32_t> vertexCode, fragmentCode;
  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
  bool depthWrite = true;
  bool blend = false;
  // Polygon offset (Vulkan's depth bias; negative: toward the eye), so that a surface drawn over
  // another where they coincide wins everywhere instead of fighting it pixel by pixel.
  float depthBiasConstant = 0.0f, depthBiasSlope = 0.0f;
  VkBool32 srgbTarget = VK_FALSE;  // shaders/target_color.glsl's constant 0

  // Throws VulkanError (the shader modules are destroyed either way).
  VkPipeline build() const;
};

}  // namespace curvefold
