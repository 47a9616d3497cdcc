// A window's render target: a VkSwapchainKHR (FIFO, so frames pace to the display) on the
// context's surface, drawn through the same MSAA scene pass as the offscreen target (finalLayout
// PRESENT_SRC). Knows nothing of the windowing library: the window's framebuffer size comes from
// a callback, so curvefold_render stays usable without a display.
//
// The swapchain and its attachments are recreated in acquire() when the size changed or the last
// acquire/present said out-of-date or suboptimal; a zero size (minimised) skips the frame.
#pragma once

#include <functional>
#include <vector>

#include "engine/render/gpu_resources.hpp"
#include "engine/render/render_target.hpp"

namespace curvefold {

class SwapchainTarget : public RenderTarget {
 public:
  // The context must have a surface (ContextOptions::createSurface) and VK_KHR_swapchain.
  SwapchainTarget(const VulkanContext& context, std::function<VkExtent2D()> framebufferSize,
                  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_4_BIT,
                  std::uint32_t framesInFlight = kFramesInFlight);
  ~SwapchainTarget() override;
  SwapchainTarget(const SwapchainTarget&) = delete;
  SwapchainTarget& operator=(const SwapchainTarget&) = delete;

  VkRenderPass renderPass() const override { return renderPass_; }
  const PassFormat& format() const override { return format_; }
  VkExtent2D extent() const override { return extent_; }
  VkFramebuffer acquire(Frame& frame) override;
  VkSemaphore acquireSemaphore(Frame& frame) const override { return frame.imageAvailable; }
  VkSemaphore presentSemaphore(Frame& frame) const override;
  void present(Frame& frame) override;

  std::uint32_t imageCount() const { return static_cast<std::uint32_t>(images_.size()); }
  std::uint32_t minImageCount() const { return minImageCount_; }
  // Recreated swapchains so far (a resize), for tests and stats.
  std::uint32_t recreations() const { return recreations_; }

 private:
  void create(VkExtent2D wanted);
  void destroySwapchain();

  const VulkanContext& context_;
  std::function<VkExtent2D()> framebufferSize_;
  PassFormat format_;
  VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkExtent2D extent_{0, 0};
  std::uint32_t minImageCount_ = 2;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  // Signalled by the submission that drew an image, waited by its present: one per image, since
  // a present may still hold the previous frame's semaphore when a frame slot comes round again.
  std::vector<VkSemaphore> renderFinished_;
  GpuImage multisampled_;
  GpuImage depth_;
  std::vector<std::uint32_t> slotImage_;  // image acquired by each frame slot
  bool stale_ = false;                    // out-of-date or suboptimal: recreate before acquiring
  std::uint32_t recreations_ = 0;
};

}  // namespace curvefold
