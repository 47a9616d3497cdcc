// Buffers and images with their memory, destroyed with their owner (move-only RAII).
#pragma once

#include <cstddef>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "engine/render/vulkan_context.hpp"

namespace curvefold {

// A host-visible, host-coherent buffer, mapped for its whole life: the CPU writes it directly and
// the writes are visible to the GPU at the next queue submission.
class HostBuffer {
 public:
  HostBuffer() = default;
  HostBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
  ~HostBuffer() { reset(); }
  HostBuffer(HostBuffer&& other) noexcept { *this = std::move(other); }
  HostBuffer& operator=(HostBuffer&& other) noexcept;
  HostBuffer(const HostBuffer&) = delete;
  HostBuffer& operator=(const HostBuffer&) = delete;

  void reset();
  VkBuffer buffer() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  std::byte* data() const { return mapped_; }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  std::byte* mapped_ = nullptr;
};

// A buffer in device memory (device-local where the device has it: a GPU's own memory), which
// only the GPU reads and writes; the CPU fills and reads it by copies through a HostBuffer.
class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  DeviceBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
  ~DeviceBuffer() { reset(); }
  DeviceBuffer(DeviceBuffer&& other) noexcept { *this = std::move(other); }
  DeviceBuffer& operator=(DeviceBuffer&& other) noexcept;
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;

  void reset();
  VkBuffer buffer() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
};

// A 2D image in device memory (preferably device-local) with one view; with layers > 1 an array
// (a multiview pass's, one layer per view) and an array view.
class GpuImage {
 public:
  GpuImage() = default;
  GpuImage(const VulkanContext& context, VkExtent2D extent, VkFormat format,
           VkSampleCountFlagBits samples, VkImageUsageFlags usage, VkImageAspectFlags aspect,
           std::uint32_t layers = 1);
  ~GpuImage() { reset(); }
  GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }
  GpuImage& operator=(GpuImage&& other) noexcept;
  GpuImage(const GpuImage&) = delete;
  GpuImage& operator=(const GpuImage&) = delete;

  void reset();
  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

}  // namespace curvefold
