// Offscreen rendering in one object: a Vulkan context (or a shared one), an OffscreenTarget, the
// frames in flight and a SceneRenderer. render() draws a scene and returns its pixels.
#pragma once

#include <memory>

#include "engine/render/frames.hpp"
#include "engine/render/image.hpp"
#include "engine/render/offscreen_target.hpp"
#include "engine/render/scene_renderer.hpp"
#include "engine/render/vulkan_context.hpp"

namespace curvefold {

struct HeadlessOptions {
  std::uint32_t width = 1280;
  std::uint32_t height = 720;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_4_BIT;  // lowered to what the device has
  bool validation = false;                                // also on when CURVEFOLD_VK_VALIDATION=1
  VkFormat color = VK_FORMAT_R8G8B8A8_UNORM;              // or R8G8B8A8_SRGB
};

class HeadlessRenderer {
 public:
  // Throws VulkanError when there is no usable Vulkan device, or too little memory to start one
  // (checkRenderMemory), in one line.
  explicit HeadlessRenderer(const HeadlessOptions& options = {});

  // Draws the scene and waits for its pixels.
  RgbaImage render(const Scene& scene);
  // Draws the scene without reading it back; waits for the GPU when `wait` (a benchmark's frame).
  void draw(const Scene& scene, bool wait = true);

  VulkanContext& context() { return *context_; }
  SceneRenderer& sceneRenderer() { return *renderer_; }
  OffscreenTarget& target() { return *target_; }
  VkSampleCountFlagBits samples() const { return target_->format().samples; }

 private:
  std::unique_ptr<VulkanContext> context_;
  std::unique_ptr<OffscreenTarget> target_;
  std::unique_ptr<FrameRing> frames_;
  std::unique_ptr<SceneRenderer> renderer_;
};

// One scene's pixels on an existing device (a window's, a headset's), through a target, frames and
// renderer made for it and gone after: a PNG export from a live session.
RgbaImage renderSceneOnce(const VulkanContext& context, const Scene& scene, VkExtent2D extent);

}  // namespace curvefold
