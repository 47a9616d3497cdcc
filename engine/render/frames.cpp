#include "engine/render/frames.hpp"

#include <limits>

#include "engine/render/scope_fail.hpp"

namespace curvefold {

FrameRing::FrameRing(const VulkanContext& context, std::uint32_t count)
    : context_(context), frames_(count) {
  const VkDevice device = context.device();
  const ScopeFail cleanup([this] { destroy(); });
  for (std::uint32_t i = 0; i < count; ++i) {
    Frame& frame = frames_[i];
    frame.slot = i;
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = context.graphicsFamily();
    vkCheck(vkCreateCommandPool(device, &pool, nullptr, &frame.pool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = frame.pool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    vkCheck(vkAllocateCommandBuffers(device, &allocate, &frame.commands),
            "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    vkCheck(vkCreateFence(device, &fence, nullptr, &frame.done), "vkCreateFence");
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    vkCheck(vkCreateSemaphore(device, &semaphore, nullptr, &frame.imageAvailable),
            "vkCreateSemaphore");
    vkCheck(vkCreateSemaphore(device, &semaphore, nullptr, &frame.renderFinished),
            "vkCreateSemaphore");
  }
}

FrameRing::~FrameRing() {
  destroy();
}

void FrameRing::destroy() {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  for (Frame& frame : frames_) {
    frame.deletions.flush();
    if (frame.imageAvailable) vkDestroySemaphore(device, frame.imageAvailable, nullptr);
    if (frame.renderFinished) vkDestroySemaphore(device, frame.renderFinished, nullptr);
    if (frame.done) vkDestroyFence(device, frame.done, nullptr);
    if (frame.pool) vkDestroyCommandPool(device, frame.pool, nullptr);  // frees its buffers
  }
  frames_.clear();
}

Frame& FrameRing::begin() {
  Frame& frame = frames_[next_];
  next_ = (next_ + 1) % count();
  wait(frame);
  frame.deletions.flush();
  vkCheck(vkResetCommandPool(context_.device(), frame.pool, 0), "vkResetCommandPool");
  VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(frame.commands, &info), "vkBeginCommandBuffer");
  return frame;
}

void FrameRing::submit(Frame& frame, VkSemaphore wait, VkPipelineStageFlags waitStage,
                       VkSemaphore signal) {
  vkCheck(vkEndCommandBuffer(frame.commands), "vkEndCommandBuffer");
  vkCheck(vkResetFences(context_.device(), 1, &frame.done), "vkResetFences");
  VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  if (wait) {
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &wait;
    info.pWaitDstStageMask = &waitStage;
  }
  info.commandBufferCount = 1;
  info.pCommandBuffers = &frame.commands;
  if (signal) {
    info.signalSemaphoreCount = 1;
    info.pSignalSemaphores = &signal;
  }
  vkCheck(vkQueueSubmit(context_.graphicsQueue(), 1, &info, frame.done), "vkQueueSubmit");
  frame.submitted = true;
}

void FrameRing::wait(const Frame& frame) const {
  vkCheck(vkWaitForFences(context_.device(), 1, &frame.done, VK_TRUE,
                          std::numeric_limits<std::uint64_t>::max()),
          "vkWaitForFences");
}

void FrameRing::waitAll() const {
  for (const Frame& frame : frames_) wait(frame);
}

}  // namespace curvefold
