#include "engine/render/headless_renderer.hpp"

#include "engine/render/render_memory.hpp"
#include "engine/text/environment_choice.hpp"

namespace curvefold {

HeadlessRenderer::HeadlessRenderer(const HeadlessOptions& options) {
  // Before the driver is loaded: out of memory inside vkCreateDevice is a crash, not an error.
  checkRenderMemory(options.width, options.height, options.samples);
  ContextOptions contextOptions;
  contextOptions.instance.validation = options.validation || vulkanValidationAsked();
  context_ = std::make_unique<VulkanContext>(contextOptions);
  target_ = std::make_unique<OffscreenTarget>(*context_, VkExtent2D{options.width, options.height},
                                              options.samples, kFramesInFlight, options.color);
  frames_ = std::make_unique<FrameRing>(*context_);
  renderer_ = std::make_unique<SceneRenderer>(*context_, *target_, frames_->count());
}

RgbaImage HeadlessRenderer::render(const Scene& scene) {
  target_->setReadback(true);
  Frame* frame = drawFrame(*frames_, *target_, *renderer_, scene);
  frames_->wait(*frame);
  return target_->readback(*frame);
}

void HeadlessRenderer::draw(const Scene& scene, bool wait) {
  target_->setReadback(false);
  Frame* frame = drawFrame(*frames_, *target_, *renderer_, scene);
  if (wait) frames_->wait(*frame);
}

RgbaImage renderSceneOnce(const VulkanContext& context, const Scene& scene, VkExtent2D extent) {
  OffscreenTarget target(context, extent);
  FrameRing frames(context);
  SceneRenderer renderer(context, target);
  renderer.markSheetReplaced();
  Frame* frame = drawFrame(frames, target, renderer, scene);
  if (!frame) throw VulkanError("offscreen frame was not drawn");
  frames.wait(*frame);
  return target.readback(*frame);
}

}  // namespace curvefold
