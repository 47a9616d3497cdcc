// A headless render target: MSAA colour and depth resolved into a single-sample RGBA8 image that
// is copied, after the render pass, into a host buffer of the frame's slot; readback() returns its
// pixels once the frame's fence has been waited.
#pragma once

#include <vector>

#include "engine/render/gpu_resources.hpp"
#include "engine/render/image.hpp"
#include "engine/render/render_target.hpp"

namespace curvefold {

class OffscreenTarget : public RenderTarget {
 public:
  // samples: wanted MSAA (4x by default), lowered to what the device supports. color: an 8-bit
  // RGBA format, UNORM or SRGB (its bytes read back the same way).
  OffscreenTarget(const VulkanContext& context, VkExtent2D extent,
                  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_4_BIT,
                  std::uint32_t framesInFlight = kFramesInFlight,
                  VkFormat color = VK_FORMAT_R8G8B8A8_UNORM);
  ~OffscreenTarget() override;

  VkRenderPass renderPass() const override { return renderPass_; }
  const PassFormat& format() const override { return format_; }
  VkExtent2D extent() const override { return extent_; }
  VkFramebuffer acquire(Frame&) override { return framebuffer_; }
  void recordAfterPass(Frame& frame) override;

  // Whether frames copy their pixels to host memory (off for a benchmark's frame time).
  void setReadback(bool enabled) { readbackEnabled_ = enabled; }
  // The frame's pixels; its fence must have been waited (FrameRing::wait).
  RgbaImage readback(const Frame& frame) const;

 private:
  const VulkanContext& context_;
  VkExtent2D extent_;
  PassFormat format_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  GpuImage multisampled_;  // absent without MSAA
  GpuImage depth_;
  GpuImage resolved_;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  std::vector<HostBuffer> readbacks_;  // one per frame slot
  bool readbackEnabled_ = true;
};

}  // namespace curvefold
