#include "engine/render/vulkan_context.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace curvefold {

const char* vkResultName(VkResult result) {
  switch (result) {
#define CURVEFOLD_RESULT(name) \
  case name:                   \
    return #name;
    CURVEFOLD_RESULT(VK_SUCCESS)
    CURVEFOLD_RESULT(VK_NOT_READY)
    CURVEFOLD_RESULT(VK_TIMEOUT)
    CURVEFOLD_RESULT(VK_INCOMPLETE)
    CURVEFOLD_RESULT(VK_SUBOPTIMAL_KHR)
    CURVEFOLD_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    CURVEFOLD_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    CURVEFOLD_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    CURVEFOLD_RESULT(VK_ERROR_DEVICE_LOST)
    CURVEFOLD_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    CURVEFOLD_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    CURVEFOLD_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    CURVEFOLD_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    CURVEFOLD_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    CURVEFOLD_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    CURVEFOLD_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    CURVEFOLD_RESULT(VK_ERROR_SURFACE_LOST_KHR)
    CURVEFOLD_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
#undef CURVEFOLD_RESULT
    default:
      return "VkResult error";
  }
}

namespace {

// lavapipe bins every frame's triangles into memory it allocates for the frame and frees after
// it. glibc hands freed memory at the top of a heap back to the kernel, so each frame faulted
// the same pages in again: a third of a 100k-triangle frame. Keeping freed memory in the process
// (up to a bound) removes that.
void keepFreedMemoryForCpuRasterizer() {
#if defined(__GLIBC__)
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
#endif
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr std::size_t kKeptMessages = 200;

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* user) {
  auto* log = static_cast<ValidationLog*>(user);
  log->count.fetch_add(1);
  std::lock_guard lock(log->mutex);
  if (log->messages.size() < kKeptMessages)
    log->messages.emplace_back(data && data->pMessage ? data->pMessage : "(no message)");
  return VK_FALSE;
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log) {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  // What the validation layer reports (its warnings and errors are of these types), not the
  // loader's own general notes, which reach the same messenger: with VK_INSTANCE_LAYERS set it
  // warns that it adds the layer, and that is no fault of ours.
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onDebugMessage;
  info.pUserData = log;
  return info;
}

bool hasLayer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
    return std::strcmp(l.layerName, name) == 0;
  });
}

bool hasInstanceExtension(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, name) == 0;
  });
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

int typeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 1;
    default:
      return 0;
  }
}

// Why a device does not fit, or empty when it does; fills the graphics family.
std::string unsuitability(VkPhysicalDevice device, const DeviceRequirements& needs,
                          std::uint32_t& family) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(device, &properties);
  if (properties.apiVersion < VK_API_VERSION_1_1) return "Vulkan 1.0 only";

  std::uint32_t extensionCount = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &extensionCount, nullptr);
  std::vector<VkExtensionProperties> extensions(extensionCount);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &extensionCount, extensions.data());
  for (const std::string& wanted : needs.extensions)
    if (std::none_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return wanted == e.extensionName; }))
      return "no " + wanted;

  std::uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, families.data());
  for (std::uint32_t i = 0; i < familyCount; ++i) {
    if (!(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
    if (needs.presentSurface != VK_NULL_HANDLE) {
      VkBool32 present = VK_FALSE;
      vkGetPhysicalDeviceSurfaceSupportKHR(device, i, needs.presentSurface, &present);
      if (!present) continue;
    }
    family = i;
    return {};
  }
  return needs.presentSurface ? "no graphics queue that presents to the window"
                              : "no graphics queue";
}

}  // namespace

InstanceBuilder::Result InstanceBuilder::build() const {
  Result result;
  std::vector<const char*> extensions;
  for (const std::string& e : options_.extensions) extensions.push_back(e.c_str());
  std::vector<const char*> layers;
  VkDebugUtilsMessengerCreateInfoEXT debugInfo{};
  if (options_.validation) {
    if (!hasLayer(kValidationLayer))
      throw VulkanError(std::string(kValidationLayer) +
                        " is not installed (Debian: vulkan-validationlayers)");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    result.log = std::make_shared<ValidationLog>();
    debugInfo = messengerInfo(result.log.get());
  }
  VkInstanceCreateFlags flags = 0;
  // MoltenVK and other non-conformant drivers are listed only with portability enumeration.
  if (hasInstanceExtension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
    extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
  }

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = options_.applicationName.c_str();
  app.pEngineName = "curvefold";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.flags = flags;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  if (options_.validation) info.pNext = &debugInfo;  // also reports instance creation itself

  if (options_.createInstance) {
    result.instance = options_.createInstance(info);
  } else {
    const VkResult created = vkCreateInstance(&info, nullptr, &result.instance);
    if (created == VK_ERROR_INCOMPATIBLE_DRIVER)
      throw VulkanError(
          "no Vulkan driver found (Debian: mesa-vulkan-drivers provides lavapipe, a CPU driver)");
    vkCheck(created, "vkCreateInstance");
  }

  if (options_.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(result.instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create || create(result.instance, &debugInfo, nullptr, &result.messenger) != VK_SUCCESS) {
      vkDestroyInstance(result.instance, nullptr);
      throw VulkanError("cannot create the Vulkan debug messenger");
    }
  }
  return result;
}

PhysicalDeviceChoice selectPhysicalDevice(VkInstance instance, const DeviceRequirements& needs) {
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  if (devices.empty())
    throw VulkanError(
        "no Vulkan device found (Debian: mesa-vulkan-drivers provides lavapipe, a CPU driver)");

  const char* forced = std::getenv("CURVEFOLD_VK_DEVICE");
  const std::string wanted = forced ? lower(forced) : std::string();
  PhysicalDeviceChoice best;
  int bestRank = -1;
  std::string seen;
  for (VkPhysicalDevice device : devices) {
    if (needs.required != VK_NULL_HANDLE && device != needs.required) continue;
    PhysicalDeviceChoice candidate{device, 0, {}};
    vkGetPhysicalDeviceProperties(device, &candidate.properties);
    const std::string name = candidate.properties.deviceName;
    std::string why = unsuitability(device, needs, candidate.graphicsFamily);
    if (why.empty() && !wanted.empty() && lower(name).find(wanted) == std::string::npos)
      why = "not CURVEFOLD_VK_DEVICE";
    seen += (seen.empty() ? "" : ", ") + name + (why.empty() ? "" : " (" + why + ")");
    if (!why.empty()) continue;
    const int rank = typeRank(candidate.properties.deviceType);
    if (rank > bestRank) {
      bestRank = rank;
      best = candidate;
    }
  }
  if (bestRank < 0) throw VulkanError("no suitable Vulkan device among: " + seen);
  return best;
}

VulkanContext::VulkanContext(const ContextOptions& options) {
  InstanceBuilder::Result instance = InstanceBuilder(options.instance).build();
  instance_ = instance.instance;
  messenger_ = instance.messenger;
  log_ = instance.log;
  try {
    DeviceRequirements needs = options.device;
    if (options.createSurface) {
      surface_ = options.createSurface(instance_);
      needs.presentSurface = surface_;
    }
    if (options.requiredPhysicalDevice) needs.required = options.requiredPhysicalDevice(instance_);
    choice_ = selectPhysicalDevice(instance_, needs);
    if (cpuDevice()) keepFreedMemoryForCpuRasterizer();
    vkGetPhysicalDeviceMemoryProperties(choice_.device, &memory_);

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = choice_.graphicsFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkPhysicalDeviceFeatures features{};  // none beyond the core
    // Multiview (both eyes in one pass) where the device has it.
    VkPhysicalDeviceMultiviewFeatures multiviewFeatures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_FEATURES};
    VkPhysicalDeviceFeatures2 available{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    available.pNext = &multiviewFeatures;
    vkGetPhysicalDeviceFeatures2(choice_.device, &available);
    multiview_ = multiviewFeatures.multiview == VK_TRUE;
    VkPhysicalDeviceMultiviewFeatures enabledMultiview{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_FEATURES};
    enabledMultiview.multiview = multiview_ ? VK_TRUE : VK_FALSE;
    std::vector<const char*> extensions;
    for (const std::string& e : needs.extensions) extensions.push_back(e.c_str());
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    info.pEnabledFeatures = &features;
    info.pNext = &enabledMultiview;
    if (options.createDevice)
      device_ = options.createDevice(choice_.device, info);
    else
      vkCheck(vkCreateDevice(choice_.device, &info, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, choice_.graphicsFamily, 0, &queue_);
  } catch (...) {
    destroyInstance();
    throw;
  }
}

VulkanContext::~VulkanContext() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyDevice(device_, nullptr);
  }
  destroyInstance();
}

// The surface, the debug messenger and the instance: what exists before the device.
void VulkanContext::destroyInstance() {
  if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  vkDestroyInstance(instance_, nullptr);
}

VkSampleCountFlagBits VulkanContext::sampleCountUpTo(VkSampleCountFlagBits wanted) const {
  const VkSampleCountFlags supported = choice_.properties.limits.framebufferColorSampleCounts &
                                       choice_.properties.limits.framebufferDepthSampleCounts;
  for (int samples = wanted; samples > 1; samples /= 2)
    if (supported & samples) return static_cast<VkSampleCountFlagBits>(samples);
  return VK_SAMPLE_COUNT_1_BIT;
}

VkSampleCountFlagBits VulkanContext::interactiveSampleCount() const {
  return cpuDevice() ? VK_SAMPLE_COUNT_1_BIT : sampleCountUpTo(VK_SAMPLE_COUNT_4_BIT);
}

std::uint32_t VulkanContext::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags flags) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & flags) == flags) return i;
  throw VulkanError("no Vulkan memory type with the needed properties");
}

std::uint32_t VulkanContext::memoryTypePreferring(std::uint32_t typeBits,
                                                  VkMemoryPropertyFlags preferred) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & preferred) == preferred)
      return i;
  return memoryType(typeBits, 0);
}

std::vector<std::string> VulkanContext::validationMessages() const {
  if (!log_) return {};
  std::lock_guard lock(log_->mutex);
  return log_->messages;
}

void VulkanContext::waitIdle() const {
  vkCheck(vkDeviceWaitIdle(device_), "vkDeviceWaitIdle");
}

}  // namespace curvefold
