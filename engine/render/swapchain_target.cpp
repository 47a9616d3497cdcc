#include "engine/render/swapchain_target.hpp"

#include <algorithm>

#include "engine/render/vulkan_objects.hpp"

namespace curvefold {

namespace {

// UNORM like the offscreen target, so a window shows the colours a PNG gets.
VkSurfaceFormatKHR chooseSurfaceFormat(VkPhysicalDevice device, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  vkCheck(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkCheck(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
  if (formats.empty()) throw VulkanError("the window surface offers no pixel format");
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
    for (const VkSurfaceFormatKHR& format : formats)
      if (format.format == wanted) return format;
  return formats.front();
}

}  // namespace

SwapchainTarget::SwapchainTarget(const VulkanContext& context,
                                 std::function<VkExtent2D()> framebufferSize,
                                 VkSampleCountFlagBits samples, std::uint32_t framesInFlight)
    : context_(context), framebufferSize_(std::move(framebufferSize)), slotImage_(framesInFlight) {
  if (context.surface() == VK_NULL_HANDLE)
    throw VulkanError("a swapchain target needs a context made with a window surface");
  const VkSurfaceFormatKHR surfaceFormat =
      chooseSurfaceFormat(context.physicalDevice(), context.surface());
  format_.color = surfaceFormat.format;
  colorSpace_ = surfaceFormat.colorSpace;
  format_.depth = chooseDepthFormat(context);
  format_.samples = context.sampleCountUpTo(samples);
  format_.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  renderPass_ = createScenePass(context.device(), format_);
  try {
    create(framebufferSize_());
  } catch (...) {
    destroySwapchain();
    vkDestroyRenderPass(context.device(), renderPass_, nullptr);
    throw;
  }
}

SwapchainTarget::~SwapchainTarget() {
  vkDeviceWaitIdle(context_.device());
  destroySwapchain();
  vkDestroyRenderPass(context_.device(), renderPass_, nullptr);
}

void SwapchainTarget::destroySwapchain() {
  const VkDevice device = context_.device();
  for (VkFramebuffer framebuffer : framebuffers_)
    vkDestroyFramebuffer(device, framebuffer, nullptr);
  for (VkImageView view : views_) vkDestroyImageView(device, view, nullptr);
  for (VkSemaphore semaphore : renderFinished_) vkDestroySemaphore(device, semaphore, nullptr);
  framebuffers_.clear();
  views_.clear();
  renderFinished_.clear();
  images_.clear();
  multisampled_.reset();
  depth_.reset();
  if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
}

void SwapchainTarget::create(VkExtent2D wanted) {
  const VkDevice device = context_.device();
  VkSurfaceCapabilitiesKHR caps{};
  vkCheck(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice(), context_.surface(),
                                                    &caps),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == 0xFFFFFFFFu) {
    // The surface takes the swapchain's size: use the window's, clamped to what it allows.
    extent.width = std::clamp(wanted.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height =
        std::clamp(wanted.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  const VkSwapchainKHR old = swapchain_;
  // Keep the old swapchain until the new one exists (oldSwapchain); free the rest of it now.
  swapchain_ = VK_NULL_HANDLE;
  destroySwapchain();
  extent_ = extent;
  if (extent.width == 0 || extent.height == 0) {
    if (old) vkDestroySwapchainKHR(device, old, nullptr);
    return;  // minimised: nothing to draw into until it has a size again
  }

  minImageCount_ = caps.minImageCount + 1;
  if (caps.maxImageCount != 0) minImageCount_ = std::min(minImageCount_, caps.maxImageCount);
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = context_.surface();
  info.minImageCount = minImageCount_;
  info.imageFormat = format_.color;
  info.imageColorSpace = colorSpace_;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                                          -caps.supportedCompositeAlpha);
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always supported; paces to the display
  info.clipped = VK_TRUE;
  info.oldSwapchain = old;
  const VkResult result = vkCreateSwapchainKHR(device, &info, nullptr, &swapchain_);
  if (old) vkDestroySwapchainKHR(device, old, nullptr);
  vkCheck(result, "vkCreateSwapchainKHR");

  std::uint32_t count = 0;
  vkCheck(vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr), "vkGetSwapchainImagesKHR");
  images_.resize(count);
  vkCheck(vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data()),
          "vkGetSwapchainImagesKHR");

  TransientAttachments transient = createTransientAttachments(context_, extent, format_);
  multisampled_ = std::move(transient.multisampled);
  depth_ = std::move(transient.depth);
  for (VkImage image : images_) {
    const VkImageView view =
        createImageView(device, image, format_.color, VK_IMAGE_ASPECT_COLOR_BIT);
    views_.push_back(view);
    const VkFramebuffer framebuffer = createSceneFramebuffer(
        device, renderPass_, format_, extent, view, depth_.view(), multisampled_.view());
    framebuffers_.push_back(framebuffer);
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    vkCheck(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &semaphore), "vkCreateSemaphore");
    renderFinished_.push_back(semaphore);
  }
}

VkFramebuffer SwapchainTarget::acquire(Frame& frame) {
  const VkExtent2D wanted = framebufferSize_();
  if (stale_ || swapchain_ == VK_NULL_HANDLE || wanted.width != extent_.width ||
      wanted.height != extent_.height) {
    if (wanted.width == 0 || wanted.height == 0) return VK_NULL_HANDLE;  // minimised
    // Frames in flight may still use the old images.
    context_.waitIdle();
    create(wanted);
    stale_ = false;
    ++recreations_;
    if (swapchain_ == VK_NULL_HANDLE) return VK_NULL_HANDLE;
  }
  std::uint32_t index = 0;
  const VkResult result = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX,
                                                frame.imageAvailable, VK_NULL_HANDLE, &index);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) {
    stale_ = true;
    return VK_NULL_HANDLE;
  }
  if (result == VK_SUBOPTIMAL_KHR)
    stale_ = true;  // the image is acquired (the semaphore will signal): draw it, then recreate
  else
    vkCheck(result, "vkAcquireNextImageKHR");
  slotImage_.at(frame.slot) = index;
  return framebuffers_[index];
}

VkSemaphore SwapchainTarget::presentSemaphore(Frame& frame) const {
  return renderFinished_[slotImage_.at(frame.slot)];
}

void SwapchainTarget::present(Frame& frame) {
  const std::uint32_t index = slotImage_.at(frame.slot);
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &renderFinished_[index];
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &index;
  const VkResult result = vkQueuePresentKHR(context_.graphicsQueue(), &info);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR)
    stale_ = true;
  else
    vkCheck(result, "vkQueuePresentKHR");
}

}  // namespace curvefold
