#include "engine/render/gpu_resources.hpp"

#include <utility>

#include "engine/render/scope_fail.hpp"
#include "engine/render/vulkan_objects.hpp"

namespace curvefold {

namespace {

// `needs.size` bytes of the memory type `type`, for a buffer or an image to bind.
VkDeviceMemory allocateMemory(VkDevice device, const VkMemoryRequirements& needs,
                              std::uint32_t type) {
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  vkCheck(vkAllocateMemory(device, &allocate, nullptr, &memory), "vkAllocateMemory");
  return memory;
}

// A buffer of `size` bytes bound to its own memory of the type `memoryType` picks among those
// the buffer allows (HostBuffer's and DeviceBuffer's one builder). Writes the handles as they
// are made, so the owner's cleanup frees whatever a failure left.
template <typename MemoryType>
void createBoundBuffer(VkDevice device, VkDeviceSize size, VkBufferUsageFlags usage,
                       const MemoryType& memoryType, VkBuffer& buffer, VkDeviceMemory& memory) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vkCheck(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(device, buffer, &needs);
  memory = allocateMemory(device, needs, memoryType(needs.memoryTypeBits));
  vkCheck(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
}

}  // namespace

HostBuffer::HostBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage)
    : device_(context.device()), size_(size) {
  const ScopeFail cleanup([this] { reset(); });
  createBoundBuffer(
      device_, size, usage,
      [&](std::uint32_t allowed) {
        return context.memoryType(
            allowed, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
      },
      buffer_, memory_);
  void* mapped = nullptr;
  vkCheck(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  mapped_ = static_cast<std::byte*>(mapped);
}

HostBuffer& HostBuffer::operator=(HostBuffer&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

void HostBuffer::reset() {
  destroyHandle(device_, buffer_, vkDestroyBuffer);
  destroyHandle(device_, memory_, vkFreeMemory);  // unmaps implicitly
  mapped_ = nullptr;
  size_ = 0;
}

DeviceBuffer::DeviceBuffer(const VulkanContext& context, VkDeviceSize size,
                           VkBufferUsageFlags usage)
    : device_(context.device()), size_(size) {
  const ScopeFail cleanup([this] { reset(); });
  createBoundBuffer(
      device_, size, usage,
      [&](std::uint32_t allowed) {
        return context.memoryTypePreferring(allowed, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      },
      buffer_, memory_);
}

DeviceBuffer& DeviceBuffer::operator=(DeviceBuffer&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

void DeviceBuffer::reset() {
  destroyHandle(device_, buffer_, vkDestroyBuffer);
  destroyHandle(device_, memory_, vkFreeMemory);
  size_ = 0;
}

GpuImage::GpuImage(const VulkanContext& context, VkExtent2D extent, VkFormat format,
                   VkSampleCountFlagBits samples, VkImageUsageFlags usage,
                   VkImageAspectFlags aspect, std::uint32_t layers)
    : device_(context.device()) {
  const ScopeFail cleanup([this] { reset(); });
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = layers;
  info.samples = samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  vkCheck(vkCreateImage(device_, &info, nullptr, &image_), "vkCreateImage");
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(device_, image_, &needs);
  memory_ = allocateMemory(
      device_, needs,
      context.memoryTypePreferring(needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT));
  vkCheck(vkBindImageMemory(device_, image_, memory_, 0), "vkBindImageMemory");
  view_ = createImageView(device_, image_, format, aspect, layers);
}

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
  }
  return *this;
}

void GpuImage::reset() {
  destroyHandle(device_, view_, vkDestroyImageView);
  destroyHandle(device_, image_, vkDestroyImage);
  destroyHandle(device_, memory_, vkFreeMemory);
}

}  // namespace curvefold
