// The simulated OpenXR runtime: swapchains and XR_KHR_vulkan_enable2 (the specification's
// "Swapchain" chapter and the extension): formats, images on the application's device, acquire,
// wait and release.
#include "sim_input/xr_runtime/runtime_state.hpp"

namespace curvefold::simxr {

XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainFormats(XrSession handle, std::uint32_t capacity,
                                                         std::uint32_t* count, std::int64_t* out) {
  return guard([&] {
    Session& session = sessionOf(handle);
    fill(session.vulkan ? swapchainFormats(session.vulkan->physicalDevice)
                        : std::vector<std::int64_t>{},
         capacity, count, out);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createSwapchain(XrSession handle, const XrSwapchainCreateInfo* info,
                                               XrSwapchain* out) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_SWAPCHAIN_CREATE_INFO);
    if (!out) return XR_ERROR_VALIDATION_FAILURE;
    if (!session.vulkan) return XR_ERROR_FEATURE_UNSUPPORTED;  // headless
    const std::vector<std::int64_t> formats = swapchainFormats(session.vulkan->physicalDevice);
    if (std::find(formats.begin(), formats.end(), info->format) == formats.end())
      return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;
    if (info->width == 0 || info->height == 0 || info->width > 4096 || info->height > 4096 ||
        info->sampleCount != 1 || info->faceCount != 1 || info->arraySize == 0 ||
        info->arraySize > kMaxSwapchainLayers || info->mipCount != 1)
      return XR_ERROR_VALIDATION_FAILURE;
    VkImageUsageFlags usage = 0;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT)
      usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)
      usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_SAMPLED_BIT) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_TRANSFER_SRC_BIT)
      usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT)
      usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (info->usageFlags & XR_SWAPCHAIN_USAGE_UNORDERED_ACCESS_BIT)
      usage |= VK_IMAGE_USAGE_STORAGE_BIT;
    auto swapchain = std::make_unique<Swapchain>();
    swapchain->session = &session;
    swapchain->images =
        std::make_unique<SwapchainImages>(*session.vulkan, VkFormat(info->format), info->width,
                                          info->height, usage, 3, info->arraySize);
    log("swapchain " + swapchainFormatName(info->format) + " " + std::to_string(info->width) + "x" +
        std::to_string(info->height) +
        (info->arraySize > 1 ? " layers=" + std::to_string(info->arraySize) : ""));
    Swapchain* created = swapchain.release();
    session.swapchains.insert(created);
    *out = handleOf<XrSwapchain>(created);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroySwapchainEntry(XrSwapchain handle) {
  return guard([&] {
    Swapchain* swapchain = objectOf<Swapchain>(handle);
    if (!swapchain) return XR_ERROR_HANDLE_INVALID;
    destroySwapchain(swapchain);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL enumerateSwapchainImages(XrSwapchain handle, std::uint32_t capacity,
                                                        std::uint32_t* count,
                                                        XrSwapchainImageBaseHeader* out) {
  return guard([&] {
    Swapchain* swapchain = objectOf<Swapchain>(handle);
    if (!swapchain) return XR_ERROR_HANDLE_INVALID;
    const auto& images = swapchain->images->images();
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = std::uint32_t(images.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < images.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    auto* vulkan = reinterpret_cast<XrSwapchainImageVulkan2KHR*>(out);
    for (std::size_t i = 0; i < images.size(); ++i) {
      if (vulkan[i].type != XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR) return XR_ERROR_VALIDATION_FAILURE;
      vulkan[i].image = images[i];
    }
    return XR_SUCCESS;
  });
}

Swapchain& swapchainOf(XrSwapchain handle) {
  Swapchain* swapchain = objectOf<Swapchain>(handle);
  if (!swapchain) fail(XR_ERROR_HANDLE_INVALID);
  liveSessionOf(reinterpret_cast<XrSession>(swapchain->session));
  return *swapchain;
}

XRAPI_ATTR XrResult XRAPI_CALL acquireSwapchainImage(XrSwapchain handle,
                                                     const XrSwapchainImageAcquireInfo*,
                                                     std::uint32_t* index) {
  return guard([&] {
    Swapchain& swapchain = swapchainOf(handle);
    if (!index) return XR_ERROR_VALIDATION_FAILURE;
    const auto size = std::uint32_t(swapchain.images->images().size());
    if (swapchain.acquired.size() >= size) return XR_ERROR_CALL_ORDER_INVALID;
    *index = swapchain.next;
    swapchain.acquired.push_back(swapchain.next);
    swapchain.next = (swapchain.next + 1) % size;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL waitSwapchainImage(XrSwapchain handle,
                                                  const XrSwapchainImageWaitInfo* info) {
  return guard([&] {
    Swapchain& swapchain = swapchainOf(handle);
    checkType(info, XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
    if (swapchain.acquired.empty() || swapchain.waited) return XR_ERROR_CALL_ORDER_INVALID;
    swapchain.waited = true;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL releaseSwapchainImage(XrSwapchain handle,
                                                     const XrSwapchainImageReleaseInfo*) {
  return guard([&] {
    Swapchain& swapchain = swapchainOf(handle);
    if (!swapchain.waited) return XR_ERROR_CALL_ORDER_INVALID;
    swapchain.waited = false;
    swapchain.lastReleased = swapchain.acquired.front();
    swapchain.acquired.pop_front();
    return XR_SUCCESS;
  });
}

// --- XR_KHR_vulkan_enable2 ---------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL getVulkanGraphicsRequirements2(
    XrInstance handle, XrSystemId system, XrGraphicsRequirementsVulkanKHR* requirements) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkSystem(system);
    checkType(requirements, XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR);
    requirements->minApiVersionSupported = XR_MAKE_VERSION(1, 0, 0);
    requirements->maxApiVersionSupported = XR_MAKE_VERSION(1, 3, 0);
    instance.requirementsCalled = true;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createVulkanInstance(XrInstance handle,
                                                    const XrVulkanInstanceCreateInfoKHR* info,
                                                    VkInstance* vulkan, VkResult* result) {
  return guard([&] {
    instanceOf(handle);
    checkType(info, XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR);
    checkSystem(info->systemId);
    if (!info->pfnGetInstanceProcAddr || !info->vulkanCreateInfo || !vulkan || !result)
      return XR_ERROR_VALIDATION_FAILURE;
    auto create = reinterpret_cast<PFN_vkCreateInstance>(
        info->pfnGetInstanceProcAddr(VK_NULL_HANDLE, "vkCreateInstance"));
    if (!create) return XR_ERROR_RUNTIME_FAILURE;
    // The simulated compositor needs nothing beyond what the application asks for.
    *result = create(info->vulkanCreateInfo, info->vulkanAllocator, vulkan);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getVulkanGraphicsDevice2(
    XrInstance handle, const XrVulkanGraphicsDeviceGetInfoKHR* info, VkPhysicalDevice* device) {
  return guard([&] {
    instanceOf(handle);
    checkType(info, XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR);
    checkSystem(info->systemId);
    if (!device || !info->vulkanInstance) return XR_ERROR_VALIDATION_FAILURE;
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(info->vulkanInstance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(info->vulkanInstance, &count, devices.data());
    if (devices.empty()) return XR_ERROR_RUNTIME_FAILURE;
    *device = devices.front();
    if (const char* wanted = std::getenv("CURVEFOLD_VK_DEVICE"))
      for (VkPhysicalDevice candidate : devices) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(candidate, &properties);
        std::string name = properties.deviceName, want = wanted;
        for (auto* s : {&name, &want})
          std::transform(s->begin(), s->end(), s->begin(),
                         [](unsigned char c) { return std::tolower(c); });
        if (name.find(want) != std::string::npos) {
          *device = candidate;
          break;
        }
      }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createVulkanDevice(XrInstance handle,
                                                  const XrVulkanDeviceCreateInfoKHR* info,
                                                  VkDevice* vulkan, VkResult* result) {
  return guard([&] {
    instanceOf(handle);
    checkType(info, XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR);
    checkSystem(info->systemId);
    if (!info->vulkanPhysicalDevice || !info->vulkanCreateInfo || !vulkan || !result)
      return XR_ERROR_VALIDATION_FAILURE;
    *result = vkCreateDevice(info->vulkanPhysicalDevice, info->vulkanCreateInfo,
                             info->vulkanAllocator, vulkan);
    return XR_SUCCESS;
  });
}

}  // namespace curvefold::simxr
