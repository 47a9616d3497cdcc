#include "sim_input/xr_runtime/vulkan_images.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include "engine/io/atomic_file.hpp"
#include "engine/render/image.hpp"
#include "engine/render/image_barrier.hpp"
#include "engine/render/scope_fail.hpp"

namespace curvefold::simxr {

namespace {

void check(VkResult result, const char* call) {
  if (result != VK_SUCCESS)
    throw std::runtime_error(std::string(call) + " failed (" + std::to_string(result) + ")");
}

bool isDepth(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D24_UNORM_S8_UINT ||
         format == VK_FORMAT_D16_UNORM;
}

std::uint32_t memoryType(VkPhysicalDevice device, std::uint32_t bits, VkMemoryPropertyFlags want) {
  VkPhysicalDeviceMemoryProperties properties;
  vkGetPhysicalDeviceMemoryProperties(device, &properties);
  for (std::uint32_t i = 0; i < properties.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (properties.memoryTypes[i].propertyFlags & want) == want) return i;
  for (std::uint32_t i = 0; i < properties.memoryTypeCount; ++i)
    if (bits & (1u << i)) return i;
  throw std::runtime_error("no Vulkan memory type for a swapchain image");
}

VkImageAspectFlags aspectOf(VkFormat format) {
  if (format == VK_FORMAT_D24_UNORM_S8_UINT)
    return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
  return isDepth(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

}  // namespace

std::string swapchainFormatName(std::int64_t format) {
  switch (static_cast<VkFormat>(format)) {
    case VK_FORMAT_R8G8B8A8_SRGB:
      return "R8G8B8A8_SRGB";
    case VK_FORMAT_B8G8R8A8_SRGB:
      return "B8G8R8A8_SRGB";
    case VK_FORMAT_R8G8B8A8_UNORM:
      return "R8G8B8A8_UNORM";
    case VK_FORMAT_B8G8R8A8_UNORM:
      return "B8G8R8A8_UNORM";
    case VK_FORMAT_D32_SFLOAT:
      return "D32_SFLOAT";
    case VK_FORMAT_D24_UNORM_S8_UINT:
      return "D24_UNORM_S8_UINT";
    case VK_FORMAT_D16_UNORM:
      return "D16_UNORM";
    default:
      return std::to_string(format);
  }
}

std::vector<std::int64_t> swapchainFormats(VkPhysicalDevice device) {
  std::vector<std::int64_t> formats = {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB,
                                       VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_UNORM};
  for (VkFormat depth : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D16_UNORM}) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device, depth, &properties);
    if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)
      formats.push_back(depth);
  }
  return formats;
}

SwapchainImages::SwapchainImages(const VulkanBinding& binding, VkFormat format, std::uint32_t width,
                                 std::uint32_t height, VkImageUsageFlags usage, std::uint32_t count,
                                 std::uint32_t layers)
    : binding_(binding),
      format_(format),
      width_(width),
      height_(height),
      layers_(layers),
      depth_(isDepth(format)) {
  const ScopeFail cleanup([this] { release(); });
  for (std::uint32_t i = 0; i < count; ++i) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage | (depth_ ? 0 : VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    check(vkCreateImage(binding.device, &info, nullptr, &image), "vkCreateImage");
    images_.push_back(image);
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(binding.device, image, &needs);
    VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = needs.size;
    allocate.memoryTypeIndex = memoryType(binding.physicalDevice, needs.memoryTypeBits,
                                          VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(binding.device, &allocate, nullptr, &memory), "vkAllocateMemory");
    memory_.push_back(memory);
    check(vkBindImageMemory(binding.device, image, memory, 0), "vkBindImageMemory");
  }
  // The extension promises images in their attachment layout, owned by the app's queue.
  const VkImageLayout layout = depth_ ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
                                      : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  submitOnce([&](VkCommandBuffer commands) {
    for (VkImage image : images_) {
      const VkAccessFlags write = depth_ ? VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT
                                         : VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
      imageBarrier(commands, image, aspectOf(format), {},
                   {layout, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, write}, layers);
    }
  });
}

SwapchainImages::~SwapchainImages() {
  release();
}

void SwapchainImages::release() {
  for (VkImage image : images_) vkDestroyImage(binding_.device, image, nullptr);
  for (VkDeviceMemory memory : memory_) vkFreeMemory(binding_.device, memory, nullptr);
  images_.clear();
  memory_.clear();
}

template <typename Record>
void SwapchainImages::submitOnce(Record record) const {
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.queueFamilyIndex = binding_.queueFamily;
  VkCommandPool pool = VK_NULL_HANDLE;
  check(vkCreateCommandPool(binding_.device, &poolInfo, nullptr, &pool), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = pool;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  VkResult result = vkAllocateCommandBuffers(binding_.device, &allocate, &commands);
  if (result == VK_SUCCESS) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(commands, &begin);
    record(commands);
    vkEndCommandBuffer(commands);
    VkQueue queue = VK_NULL_HANDLE;
    vkGetDeviceQueue(binding_.device, binding_.queueFamily, binding_.queueIndex, &queue);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    result = vkQueueSubmit(queue, 1, &submit, VK_NULL_HANDLE);
    if (result == VK_SUCCESS) result = vkQueueWaitIdle(queue);
  }
  vkDestroyCommandPool(binding_.device, pool, nullptr);
  check(result, "a simulated runtime's submission");
}

void SwapchainImages::savePng(std::uint32_t index, std::uint32_t layer,
                              const std::filesystem::path& path) const {
  if (depth_ || index >= images_.size() || layer >= layers_) return;
  const VkDeviceSize size = VkDeviceSize(width_) * height_ * 4;
  VkBufferCreateInfo bufferInfo{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bufferInfo.size = size;
  bufferInfo.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  check(vkCreateBuffer(binding_.device, &bufferInfo, nullptr, &buffer), "vkCreateBuffer");
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(binding_.device, buffer, &needs);
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex =
      memoryType(binding_.physicalDevice, needs.memoryTypeBits,
                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(binding_.device, &allocate, nullptr, &memory), "vkAllocateMemory");
  vkBindBufferMemory(binding_.device, buffer, memory, 0);
  const VkImage image = images_[index];
  submitOnce([&](VkCommandBuffer commands) {
    // The attachment layout the app renders in, to a copy's, and back after the copy.
    const ImageUse attachment{VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                              VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                              VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
    const ImageUse copy{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_TRANSFER_READ_BIT};
    imageBarrier(commands, image, VK_IMAGE_ASPECT_COLOR_BIT, attachment, copy, layers_);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, layer, 1};
    region.imageExtent = {width_, height_, 1};
    vkCmdCopyImageToBuffer(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1,
                           &region);
    imageBarrier(commands, image, VK_IMAGE_ASPECT_COLOR_BIT, copy, attachment, layers_);
    VkBufferMemoryBarrier host{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    host.srcQueueFamilyIndex = host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    host.buffer = buffer;
    host.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                         nullptr, 1, &host, 0, nullptr);
  });
  RgbaImage picture;
  picture.width = width_;
  picture.height = height_;
  picture.pixels.resize(size);
  void* mapped = nullptr;
  check(vkMapMemory(binding_.device, memory, 0, size, 0, &mapped), "vkMapMemory");
  std::memcpy(picture.pixels.data(), mapped, size);
  vkUnmapMemory(binding_.device, memory);
  vkDestroyBuffer(binding_.device, buffer, nullptr);
  vkFreeMemory(binding_.device, memory, nullptr);
  if (format_ == VK_FORMAT_B8G8R8A8_SRGB || format_ == VK_FORMAT_B8G8R8A8_UNORM)
    for (std::size_t i = 0; i < picture.pixels.size(); i += 4)
      std::swap(picture.pixels[i], picture.pixels[i + 2]);
  writeFileAtomically(path, encodePng(picture));
}

}  // namespace curvefold::simxr
