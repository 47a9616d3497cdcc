#include "app/xr/xr_vulkan_graphics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/render/scope_fail.hpp"
#include "engine/render/vulkan_error.hpp"
#include "engine/render/vulkan_objects.hpp"
#include "interaction/xr/xr_check.hpp"

namespace curvefold::xr {

namespace {

bool isDepthFormat(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D24_UNORM_S8_UINT ||
         format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

// A view of a swapchain image: all its layers (an array view for a multiview pass).
VkImageView createView(VkDevice device, VkImage image, VkFormat format, std::uint32_t layers) {
  VkImageAspectFlags aspect =
      isDepthFormat(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
  if (format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT)
    aspect |= VK_IMAGE_ASPECT_STENCIL_BIT;
  return createImageView(device, image, format, aspect, layers);
}

// A Vulkan instance or device the runtime makes with `create` (xrCreateVulkanInstanceKHR or
// xrCreateVulkanDeviceKHR, named `name`): the runtime's failure and Vulkan's are reported apart.
template <typename Handle, typename Create, typename CreateInfo>
Handle createByRuntime(Create create, const char* name, XrInstance instance, const CreateInfo& info,
                       const char* vulkanCall) {
  Handle vulkan = VK_NULL_HANDLE;
  VkResult result = VK_SUCCESS;
  xrCheck(create(instance, &info, &vulkan, &result), name, __FILE__, __LINE__);
  vkCheck(result, (std::string(name) + "'s " + vulkanCall).c_str());
  return vulkan;
}

std::vector<VkImage> swapchainImages(XrSwapchain swapchain) {
  if (swapchain == XR_NULL_HANDLE) return {};
  std::uint32_t count = 0;
  CHECK_XR(xrEnumerateSwapchainImages(swapchain, 0, &count, nullptr));
  std::vector<XrSwapchainImageVulkan2KHR> images(count, {XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR});
  CHECK_XR(xrEnumerateSwapchainImages(
      swapchain, count, &count, reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())));
  std::vector<VkImage> result;
  for (const auto& image : images) result.push_back(image.image);
  return result;
}

}  // namespace

Camera eyeCamera(const XrPosef& pose, const XrFovf& fov, float nearPlane, float farPlane) {
  const glm::quat orientation(pose.orientation.w, pose.orientation.x, pose.orientation.y,
                              pose.orientation.z);
  const glm::vec3 position(pose.position.x, pose.position.y, pose.position.z);
  glm::mat4 worldFromEye = glm::mat4_cast(orientation);
  worldFromEye[3] = glm::vec4(position, 1.0f);

  const float left = std::tan(fov.angleLeft), right = std::tan(fov.angleRight);
  const float up = std::tan(fov.angleUp), down = std::tan(fov.angleDown);
  const float width = right - left, height = up - down;
  glm::mat4 projection(0.0f);
  projection[0][0] = 2.0f / width;
  projection[2][0] = (right + left) / width;
  projection[1][1] = -2.0f / height;  // Vulkan's y points down
  projection[2][1] = -(up + down) / height;
  projection[2][2] = farPlane / (nearPlane - farPlane);
  projection[2][3] = -1.0f;
  projection[3][2] = nearPlane * farPlane / (nearPlane - farPlane);

  Camera camera;
  camera.eye = position;
  camera.target = position + orientation * glm::vec3(0.0f, 0.0f, -1.0f);
  camera.up = orientation * glm::vec3(0.0f, 1.0f, 0.0f);
  camera.nearPlane = nearPlane;
  camera.farPlane = farPlane;
  camera.fovYDegrees = glm::degrees(fov.angleUp - fov.angleDown);
  camera.viewMatrix = glm::affineInverse(worldFromEye);
  camera.projectionMatrix = projection;
  return camera;
}

XrEyeTarget::XrEyeTarget(const VulkanContext& context, const XrViewSwapchains& swapchains,
                         const std::vector<VkImage>& colorImages,
                         const std::vector<VkImage>& depthImages)
    : context_(context),
      extent_{std::uint32_t(swapchains.extent.width), std::uint32_t(swapchains.extent.height)} {
  format_.color = static_cast<VkFormat>(swapchains.colorFormat);
  format_.samples = context.sampleCountUpTo(static_cast<VkSampleCountFlagBits>(swapchains.samples));
  format_.depth = swapchains.depthFormat != 0 ? static_cast<VkFormat>(swapchains.depthFormat)
                                              : chooseDepthFormat(context);
  // The runtime takes the image back in the layout it gave it (XR_KHR_vulkan_enable2).
  format_.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  // An array swapchain holds every view: one multiview pass draws them all.
  format_.views = swapchains.arraySize;
  renderPass_ = createScenePass(context.device(), format_);
  const ScopeFail cleanup([this] { destroy(); });
  transient_ = createTransientAttachments(context, extent_, format_);
  if (!depthImages.empty()) transient_.depth = GpuImage();  // the swapchain's depth serves
  for (VkImage image : colorImages)
    colorViews_.push_back(createView(context.device(), image, format_.color, format_.views));
  for (VkImage image : depthImages)
    depthViews_.push_back(createView(context.device(), image, format_.depth, format_.views));
}

XrEyeTarget::~XrEyeTarget() {
  destroy();
}

void XrEyeTarget::destroy() {
  const VkDevice device = context_.device();
  for (auto& [images, framebuffer] : framebuffers_)
    vkDestroyFramebuffer(device, framebuffer, nullptr);
  framebuffers_.clear();
  for (VkImageView view : colorViews_) vkDestroyImageView(device, view, nullptr);
  for (VkImageView view : depthViews_) vkDestroyImageView(device, view, nullptr);
  colorViews_.clear();
  depthViews_.clear();
  destroyHandle(device, renderPass_, vkDestroyRenderPass);
}

void XrEyeTarget::use(std::uint32_t colorImage, std::optional<std::uint32_t> depthImage) {
  color_ = colorImage;
  depth_ = depthImage;
}

VkFramebuffer XrEyeTarget::acquire(Frame&) {
  const bool swapchainDepth = !depthViews_.empty();
  if (color_ >= colorViews_.size() ||
      (swapchainDepth && (!depth_ || *depth_ >= depthViews_.size())))
    throw VulkanError("XR eye: swapchain image index out of range");
  const std::pair key{color_, swapchainDepth ? *depth_ : 0u};
  if (auto found = framebuffers_.find(key); found != framebuffers_.end()) return found->second;
  const VkImageView depth = swapchainDepth ? depthViews_[key.second] : transient_.depth.view();
  const VkFramebuffer framebuffer =
      createSceneFramebuffer(context_.device(), renderPass_, format_, extent_,
                             colorViews_[key.first], depth, transient_.multisampled.view());
  framebuffers_[key] = framebuffer;
  return framebuffer;
}

XrVulkanGraphics::XrVulkanGraphics(bool validation, XrMultiview multiview)
    : validation_(validation), multiview_(multiview) {}

std::uint32_t XrVulkanGraphics::viewsPerSwapchain() const {
  if (!context_ || !context_->multiview() || multiview_ == XrMultiview::Off) return 1;
  if (multiview_ == XrMultiview::Auto && context_->cpuDevice()) return 1;
  return 2;
}

XrVulkanGraphics::~XrVulkanGraphics() {
  swapchainsDestroyed();
}

std::vector<std::string> XrVulkanGraphics::instanceExtensions() const {
  return {"XR_KHR_vulkan_enable2"};
}

void XrVulkanGraphics::initializeDevice(XrInstance instance, XrSystemId system) {
  instance_ = instance;
  auto requirements = xrFunction<PFN_xrGetVulkanGraphicsRequirements2KHR>(
      instance, "xrGetVulkanGraphicsRequirements2KHR");
  auto deviceForSystem =
      xrFunction<PFN_xrGetVulkanGraphicsDevice2KHR>(instance, "xrGetVulkanGraphicsDevice2KHR");
  XrGraphicsRequirementsVulkan2KHR needs{XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR};
  CHECK_XR(requirements(instance, system, &needs));
  if (XR_VERSION_MAJOR(needs.minApiVersionSupported) > 1 ||
      XR_VERSION_MINOR(needs.minApiVersionSupported) > 3)
    throw XrError("the OpenXR runtime needs a newer Vulkan than 1.3", XR_ERROR_RUNTIME_FAILURE);

  auto physicalDevice = [instance, system, deviceForSystem](VkInstance vulkan) {
    XrVulkanGraphicsDeviceGetInfoKHR info{XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR};
    info.systemId = system;
    info.vulkanInstance = vulkan;
    VkPhysicalDevice device = VK_NULL_HANDLE;
    CHECK_XR(deviceForSystem(instance, &info, &device));
    return device;
  };
  if (context_) {
    // A new session after a loss: the device made before must still be the runtime's.
    if (physicalDevice(context_->instance()) != context_->physicalDevice())
      throw XrError("the OpenXR runtime moved to another GPU; restart curvefold xr",
                    XR_ERROR_RUNTIME_FAILURE);
    return;
  }

  auto createInstance =
      xrFunction<PFN_xrCreateVulkanInstanceKHR>(instance, "xrCreateVulkanInstanceKHR");
  auto createDevice = xrFunction<PFN_xrCreateVulkanDeviceKHR>(instance, "xrCreateVulkanDeviceKHR");
  ContextOptions options;
  options.instance.applicationName = "curvefold xr";
  options.instance.validation = validation_;
  options.instance.createInstance = [=](const VkInstanceCreateInfo& info) {
    XrVulkanInstanceCreateInfoKHR create{XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR};
    create.systemId = system;
    create.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
    create.vulkanCreateInfo = &info;
    return createByRuntime<VkInstance>(createInstance, "xrCreateVulkanInstanceKHR", instance,
                                       create, "vkCreateInstance");
  };
  options.requiredPhysicalDevice = physicalDevice;
  options.createDevice = [=](VkPhysicalDevice device, const VkDeviceCreateInfo& info) {
    XrVulkanDeviceCreateInfoKHR create{XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR};
    create.systemId = system;
    create.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
    create.vulkanPhysicalDevice = device;
    create.vulkanCreateInfo = &info;
    return createByRuntime<VkDevice>(createDevice, "xrCreateVulkanDeviceKHR", instance, create,
                                     "vkCreateDevice");
  };
  context_ = std::make_unique<VulkanContext>(options);
  binding_.type = XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR;
  binding_.instance = context_->instance();
  binding_.physicalDevice = context_->physicalDevice();
  binding_.device = context_->device();
  binding_.queueFamilyIndex = context_->graphicsFamily();
  binding_.queueIndex = 0;
}

std::int64_t XrVulkanGraphics::chooseColorFormat(std::span<const std::int64_t> offered) const {
  // sRGB first, as compositors expect (hello_xr's order): given linear colour, it shows what a
  // UNORM target shows of sRGB-encoded colour, where a compositor would encode UNORM a second time.
  for (VkFormat wanted : {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB,
                          VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_UNORM})
    if (std::find(offered.begin(), offered.end(), wanted) != offered.end()) return wanted;
  throw XrError("the OpenXR runtime offers no 8-bit RGBA swapchain format",
                XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED);
}

std::int64_t XrVulkanGraphics::chooseDepthFormat(std::span<const std::int64_t> offered,
                                                 std::uint32_t samples) const {
  if (samples > 1) return 0;  // MSAA depth lives inside the pass; a swapchain's has one sample
  for (VkFormat wanted : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D16_UNORM})
    if (std::find(offered.begin(), offered.end(), wanted) != offered.end()) return wanted;
  return 0;
}

std::uint32_t XrVulkanGraphics::chooseSampleCount(const XrViewConfigurationView& view) const {
  const std::uint32_t wanted =
      std::clamp(view.recommendedSwapchainSampleCount, 1u, view.maxSwapchainSampleCount);
  return static_cast<std::uint32_t>(
      context_->sampleCountUpTo(static_cast<VkSampleCountFlagBits>(std::min(wanted, 8u))));
}

void XrVulkanGraphics::swapchainsCreated(std::uint32_t view, const XrViewSwapchains& swapchains) {
  if (targets_.size() <= view) targets_.resize(view + 1);
  targets_[view] = std::make_unique<XrEyeTarget>(
      *context_, swapchains, swapchainImages(swapchains.color), swapchainImages(swapchains.depth));
  if (!renderer_) {
    frames_ = std::make_unique<FrameRing>(*context_, framesInFlight());
    renderer_ = std::make_unique<SceneRenderer>(*context_, *targets_[view], framesInFlight());
    renderer_->markSheetReplaced();
    ++rendererGeneration_;
  }
}

void XrVulkanGraphics::swapchainsDestroyed() {
  if (frames_) frames_->waitAll();
  renderer_.reset();
  frames_.reset();
  targets_.clear();
}

void XrVulkanGraphics::renderViews(std::span<const XrEyeView> eyes) {
  if (targets_.empty() || targets_[0]->format().views < 2) {
    XrGraphics::renderViews(eyes);  // an eye at a time
    return;
  }
  // One multiview pass: both eyes' cameras, one frame slot, one submission.
  XrEyeTarget& target = *targets_[0];
  target.use(eyes[0].colorImage, eyes[0].depthImage);
  std::vector<Camera> cameras;
  for (const XrEyeView& eye : eyes)
    cameras.push_back(eyeCamera(eye.pose, eye.fov, nearPlane(), farPlane()));
  const Scene& scene = eyeScene_(cameras);
  if (!drawFrame(*frames_, target, *renderer_, scene, {}, beforeEyes_))
    throw VulkanError("XR views were not drawn");
}

void XrVulkanGraphics::renderEye(const XrEyeView& eye) {
  XrEyeTarget& target = *targets_.at(eye.index);
  target.use(eye.colorImage, eye.depthImage);
  const Camera camera = eyeCamera(eye.pose, eye.fov, nearPlane(), farPlane());
  const Scene& scene = eyeScene_(std::span<const Camera>(&camera, 1));
  const PassOverlay& before = eye.index == 0 ? beforeEyes_ : PassOverlay{};
  if (!drawFrame(*frames_, target, *renderer_, scene, {}, before))
    throw VulkanError("XR eye " + std::to_string(eye.index) + " was not drawn");
}

}  // namespace curvefold::xr
