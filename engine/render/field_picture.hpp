// A picture of a quantity on the sheet (issue 38 2d: a fit's distance to its target; issue 39:
// a simulated state's strain or crease angle error): the sheet rendered with one value per vertex
// through a colour map (color_map.hpp), its creases in grey so they do not read as values, and
// the legend (color_legend.hpp) in a strip at the right that the 3D view leaves free.
#pragma once

#include <optional>
#include <span>

#include "engine/geometry/sheet.hpp"
#include "engine/render/color_legend.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/scene_builder.hpp"

namespace curvefold {

// vertexValues: one per sheet vertex (throws std::invalid_argument otherwise), mapped with
// legend.low at the map's low end and legend.high at its high end. The picture is the renderer's
// size. view: a named view, or nothing to choose one from the sheet (sheet_view.hpp: a nearly
// flat sheet laid down and seen from above at an angle, whatever plane it lies in).
RgbaImage renderFieldPicture(HeadlessRenderer& renderer, const Sheet& sheet,
                             std::span<const double> vertexValues, const ColorLegend& legend,
                             std::optional<ViewPreset> view = std::nullopt);

}  // namespace curvefold
