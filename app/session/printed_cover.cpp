#include "app/session/printed_cover.hpp"

#include <exception>
#include <new>

#include "engine/render/headless_renderer.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/render/vulkan_context.hpp"
#include "engine/render/vulkan_error.hpp"

namespace curvefold::session {

std::optional<PdfPicture> renderFoldedForm(const Sheet& sheet, std::string& problem) {
  try {
    HeadlessOptions options;
    options.width = 1200;
    options.height = 800;
    HeadlessRenderer renderer(options);
    const RgbaImage image = renderer.render(
        sceneForSheet(sheet, ViewPreset::Iso, float(options.width) / float(options.height), false));
    checkValidation(renderer.context());
    return PdfPicture{image.width, image.height, image.pixels};
  } catch (const std::bad_alloc&) {
    problem = "out of memory";
  } catch (const std::exception& e) {
    problem = e.what();
  }
  return std::nullopt;
}

void checkValidation(const VulkanContext& context) {
  if (context.validationMessageCount() == 0) return;
  std::string first = context.validationMessages().front();
  first = first.substr(0, first.find('\n'));
  throw VulkanError(std::to_string(context.validationMessageCount()) +
                    " Vulkan validation messages, the first: " + first);
}

}  // namespace curvefold::session
