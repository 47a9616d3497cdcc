// Where frames go. A RenderTarget owns the images and the render pass a SceneRenderer draws with;
// the offscreen target (offscreen_target.hpp) reads pixels back, and a window's swapchain target
// implements the same interface (acquire waits on the swapchain image, present queues it), so one
// SceneRenderer and one drawFrame() loop serve both.
//
// Every target uses createScenePass(): an MSAA colour and depth attachment resolved into a
// single-sample colour attachment (or drawn into it directly when the device has no MSAA), so a
// SceneRenderer built for one target works with any other of the same PassFormat.
#pragma once

#include <vulkan/vulkan.h>
#include <glm/vec4.hpp>

#include "engine/render/frames.hpp"
#include "engine/render/gpu_resources.hpp"
#include "engine/render/vulkan_context.hpp"

namespace curvefold {

struct PassFormat {
  VkFormat color = VK_FORMAT_R8G8B8A8_UNORM;  // of the single-sample (resolved) image
  VkFormat depth = VK_FORMAT_D32_SFLOAT;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_4_BIT;
  // Layout the resolved image ends in: TRANSFER_SRC for a readback, PRESENT_SRC for a swapchain.
  VkImageLayout finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  // Views drawn at once (VK_KHR_multiview, core in Vulkan 1.1): 2 for both eyes in one pass into
  // two-layer images, layer i seen from view i. 1: an ordinary pass.
  std::uint32_t views = 1;
};

// Whether the format encodes linear values as sRGB on write (the *_SRGB formats).
bool isSrgbFormat(VkFormat format);
// A colour chosen as sRGB-encoded values, as the target must be given it: as is for a UNORM
// target, decoded to linear for an sRGB one (which encodes it again), so both show the same.
glm::vec4 targetColor(const glm::vec4& srgbEncoded, const PassFormat& format);

// Attachments: 0 = colour (MSAA when samples > 1), 1 = depth, 2 = resolve (only when samples > 1).
VkRenderPass createScenePass(VkDevice device, const PassFormat& format);
// The pass's transient attachments: the MSAA colour image (absent without MSAA) and the depth
// image, which live only inside the render pass.
struct TransientAttachments {
  GpuImage multisampled;
  GpuImage depth;
};
TransientAttachments createTransientAttachments(const VulkanContext& context, VkExtent2D extent,
                                                const PassFormat& format);

// A framebuffer of createScenePass(): `image` is the final single-sample colour image, `depth` the
// depth view, `multisampled` the MSAA colour view (ignored without MSAA); the attachments are put
// in the pass's order here, so no target has to know it.
VkFramebuffer createSceneFramebuffer(VkDevice device, VkRenderPass pass, const PassFormat& format,
                                     VkExtent2D extent, VkImageView image, VkImageView depth,
                                     VkImageView multisampled);

// A depth format the device can use as a depth attachment (D32, else D24S8, else D16).
VkFormat chooseDepthFormat(const VulkanContext& context);

class RenderTarget {
 public:
  virtual ~RenderTarget() = default;

  virtual VkRenderPass renderPass() const = 0;
  virtual const PassFormat& format() const = 0;
  virtual VkExtent2D extent() const = 0;

  // Starts a frame and returns the framebuffer to draw into; VK_NULL_HANDLE means no image this
  // time (a minimised or resized window: recreate the target and try the next frame).
  virtual VkFramebuffer acquire(Frame& frame) = 0;
  // The semaphore the frame's submission must wait for (a swapchain image), if any.
  virtual VkSemaphore acquireSemaphore(Frame&) const { return VK_NULL_HANDLE; }
  // The semaphore the submission signals for present(), if any.
  virtual VkSemaphore presentSemaphore(Frame&) const { return VK_NULL_HANDLE; }
  // Commands after the render pass, in the same command buffer (the offscreen readback copy).
  virtual void recordAfterPass(Frame&) {}
  // After submission (a swapchain presents here).
  virtual void present(Frame&) {}
};

}  // namespace curvefold
