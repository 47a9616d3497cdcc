// The Vulkan graphics plugin of the XR program (hello_xr's VulkanGraphicsPlugin, over our
// renderer): the instance, physical device and device made through the runtime
// (XR_KHR_vulkan_enable2), an XrEyeTarget per view over the runtime's swapchain images, and the
// one SceneRenderer drawing each eye's Scene.
//
// Each eye is its own frame in flight (the ring has two slots per eye), so an eye's uniforms and
// sheet buffers are never rewritten while the GPU reads them; the sheet's dirty ranges reach
// every slot (scene_renderer.hpp). MSAA follows the runtime's recommended sample count; with one
// sample the depth swapchain, when offered, is the pass's depth attachment.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>
// OpenXR's Vulkan types need Vulkan's header first.
#define XR_USE_GRAPHICS_API_VULKAN
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "engine/render/frames.hpp"
#include "engine/render/render_target.hpp"
#include "engine/render/scene.hpp"
#include "engine/render/scene_renderer.hpp"
#include "engine/render/vulkan_context.hpp"
#include "interaction/xr/xr_program.hpp"

namespace curvefold::xr {

// How the eyes are drawn. On: both in one pass into an array swapchain (VK_KHR_multiview) where
// the device has multiview. Off: a pass per eye. Auto: On, except on a CPU device: Debian 12's
// lavapipe (Mesa 22.3) draws triangles that the view's edge clips into the first eye's layer in a
// multiview pass, so a panel crossing the edge of sight vanishes from the right eye and shows
// twice in the left (seen in `curvefold xr` with the simulated runtime; README, Performance).
enum class XrMultiview { Auto, On, Off };

// One view's swapchain images as a render target; use() picks the acquired images.
class XrEyeTarget : public RenderTarget {
 public:
  XrEyeTarget(const VulkanContext& context, const XrViewSwapchains& swapchains,
              const std::vector<VkImage>& colorImages, const std::vector<VkImage>& depthImages);
  ~XrEyeTarget() override;
  XrEyeTarget(const XrEyeTarget&) = delete;
  XrEyeTarget& operator=(const XrEyeTarget&) = delete;

  VkRenderPass renderPass() const override { return renderPass_; }
  const PassFormat& format() const override { return format_; }
  VkExtent2D extent() const override { return extent_; }
  void use(std::uint32_t colorImage, std::optional<std::uint32_t> depthImage);
  VkFramebuffer acquire(Frame& frame) override;

 private:
  void destroy();

  const VulkanContext& context_;
  PassFormat format_;
  VkExtent2D extent_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  TransientAttachments transient_;  // MSAA colour, and depth when no depth swapchain serves
  std::vector<VkImageView> colorViews_, depthViews_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, VkFramebuffer> framebuffers_;
  std::uint32_t color_ = 0;
  std::optional<std::uint32_t> depth_;
};

class XrVulkanGraphics : public XrGraphics {
 public:
  // The scene seen by these cameras (one eye's, or both eyes' for a multiview pass: the scene's
  // camera and secondView).
  using EyeScene = std::function<const Scene&(std::span<const Camera> cameras)>;
  explicit XrVulkanGraphics(bool validation, XrMultiview multiview = XrMultiview::Auto);
  ~XrVulkanGraphics() override;

  std::vector<std::string> instanceExtensions() const override;
  void initializeDevice(XrInstance instance, XrSystemId system) override;
  const void* sessionBinding() const override { return &binding_; }
  std::int64_t chooseColorFormat(std::span<const std::int64_t> offered) const override;
  std::int64_t chooseDepthFormat(std::span<const std::int64_t> offered,
                                 std::uint32_t samples) const override;
  std::uint32_t chooseSampleCount(const XrViewConfigurationView& view) const override;
  void swapchainsCreated(std::uint32_t view, const XrViewSwapchains& swapchains) override;
  void swapchainsDestroyed() override;
  void renderEye(const XrEyeView& eye) override;
  std::uint32_t viewsPerSwapchain() const override;
  void renderViews(std::span<const XrEyeView> eyes) override;
  float nearPlane() const override { return 0.01f; }
  float farPlane() const override { return 100.0f; }

  void setEyeScene(EyeScene eyeScene) { eyeScene_ = std::move(eyeScene); }
  // Commands recorded once a frame before the first eye's pass, in its command buffer (drawing
  // the panel's picture that both eyes then sample).
  void setBeforeEyes(PassOverlay beforeEyes) { beforeEyes_ = std::move(beforeEyes); }
  // Null before initializeDevice.
  const VulkanContext* context() const { return context_.get(); }
  // Null while there are no swapchains.
  SceneRenderer* renderer() { return renderer_.get(); }
  // Frames that may be on the GPU at once (the ring's slots).
  std::uint32_t framesInFlight() const { return 2 * kFramesInFlight; }
  // Counts the renderers made (a new one after a lost session needs what the last was given).
  std::uint64_t rendererGeneration() const { return rendererGeneration_; }

 private:
  bool validation_;
  XrMultiview multiview_;
  XrInstance instance_ = XR_NULL_HANDLE;
  std::unique_ptr<VulkanContext> context_;
  XrGraphicsBindingVulkan2KHR binding_{};
  std::vector<std::unique_ptr<XrEyeTarget>> targets_;
  std::unique_ptr<FrameRing> frames_;
  std::unique_ptr<SceneRenderer> renderer_;
  EyeScene eyeScene_;
  PassOverlay beforeEyes_;
  std::uint64_t rendererGeneration_ = 0;
};

// The camera of an eye: its pose as the view and its four half-angles as an off-centre Vulkan
// frustum (y down, depth 0 to 1).
Camera eyeCamera(const XrPosef& pose, const XrFovf& fov, float nearPlane, float farPlane);

}  // namespace curvefold::xr
