// Frames in flight: each slot has its own command pool and buffer, a fence that says when the GPU
// has finished with it, semaphores for a swapchain, and a deletion queue for objects the slot's
// last submission may still use. Slot i is only written again after its fence, so everything
// kept per slot (the sheet's vertex buffers, per-frame uniforms) is never written while read.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/render/deletion_queue.hpp"
#include "engine/render/vulkan_context.hpp"

namespace curvefold {

inline constexpr std::uint32_t kFramesInFlight = 2;

struct Frame {
  std::uint32_t slot = 0;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  VkFence done = VK_NULL_HANDLE;                // signalled when this slot's submission finished
  VkSemaphore imageAvailable = VK_NULL_HANDLE;  // for a swapchain's acquire
  VkSemaphore renderFinished = VK_NULL_HANDLE;  // for a swapchain's present
  DeletionQueue deletions;                      // flushed when the slot is begun again
  bool submitted = false;
};

class FrameRing {
 public:
  explicit FrameRing(const VulkanContext& context, std::uint32_t count = kFramesInFlight);
  ~FrameRing();
  FrameRing(const FrameRing&) = delete;
  FrameRing& operator=(const FrameRing&) = delete;

  std::uint32_t count() const { return static_cast<std::uint32_t>(frames_.size()); }
  // Moves to the next slot: waits for its previous submission, runs its deletions, resets its
  // command pool and begins recording.
  Frame& begin();
  // Ends recording and submits; waits on `wait` at `waitStage` and signals `signal` when given.
  void submit(Frame& frame, VkSemaphore wait = VK_NULL_HANDLE,
              VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
              VkSemaphore signal = VK_NULL_HANDLE);
  // Blocks until the frame's submission has finished.
  void wait(const Frame& frame) const;
  void waitAll() const;

 private:
  void destroy();

  const VulkanContext& context_;
  std::vector<Frame> frames_;
  std::uint32_t next_ = 0;
};

}  // namespace curvefold
