#include "engine/render/field_picture.hpp"

#include <stdexcept>
#include <vector>

#include "engine/render/sheet_view.hpp"

namespace curvefold {

RgbaImage renderFieldPicture(HeadlessRenderer& renderer, const Sheet& sheet,
                             std::span<const double> vertexValues, const ColorLegend& legend,
                             std::optional<ViewPreset> view) {
  if (vertexValues.size() != sheet.vertexCount())
    throw std::invalid_argument("renderFieldPicture: one value per vertex is needed");
  const VkExtent2D extent = renderer.target().extent();
  const std::uint32_t strip = legendWidth(extent.width);
  const bool withLegend = extent.width > strip * 2;
  const std::uint32_t viewWidth = withLegend ? extent.width - strip : extent.width;
  const float aspect = float(viewWidth) / float(std::max(extent.height, 1u));
  Scene scene;
  if (view) {
    scene = sceneForSheet(sheet, *view, aspect, false);
  } else {
    const SheetView chosen = viewForSheet(sheet);
    scene = sceneForSheet(sheet, chosen.direction, aspect, false, chosen.worldFromSheet);
  }
  if (withLegend) {
    // The strip is the scene's side panel, empty: the view is framed beside it, not under it.
    scene.panel.enabled = true;
    scene.panel.widthFraction = (float(strip) + 0.5f) / float(extent.width);
    scene.colors.panelBackground = scene.colors.background;
  }
  for (LineSegment& crease : scene.creases)
    crease.color = glm::vec4(0.15f, 0.15f, 0.15f, crease.color.a);
  const std::vector<glm::u8vec4> colors =
      colorsOf(vertexValues, legend.low, legend.high, legend.map);
  scene.sheet.vertexColors = colors;
  renderer.sceneRenderer().markSheetReplaced();
  RgbaImage image = renderer.render(scene);
  renderer.sceneRenderer().markSheetReplaced();
  if (withLegend) drawColorLegend(image, legend);
  return image;
}

}  // namespace curvefold
