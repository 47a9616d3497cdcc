// Perceptual colour maps for a scalar on the sheet (issue 38 2d, issue 39 1): a sequential map
// (viridis: Smith and van der Walt's matplotlib default, perceptually uniform and readable in grey
// and by colour-blind eyes) for a magnitude from 0 (a distance, a strain), and a diverging one
// (Moreland's cool-warm, "Diverging Color Maps for Scientific Visualization", ISVC 2009) for a
// signed error around 0. Both are the published maps sampled at a few stops and interpolated
// linearly in sRGB, which keeps them within a level or two of the full tables.
//
// Colours are sRGB-encoded bytes, what a PNG holds and the renderer's per-vertex colours take
// (SceneSheet::vertexColors).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <glm/ext/vector_uint4_sized.hpp>

namespace curvefold {

enum class ColorMap : std::uint8_t {
  Viridis,   // dark purple (low) -> blue -> green -> yellow (high)
  CoolWarm,  // blue (low) -> light grey (middle) -> red (high)
};

// The map's colour at t in [0, 1] (clamped; NaN gives the low end), alpha 255.
glm::u8vec4 colorAt(ColorMap map, double t);

// Each value's colour with `low` at t = 0 and `high` at t = 1 (equal bounds map everything to
// the middle); a value that is not finite gets the low end.
std::vector<glm::u8vec4> colorsOf(std::span<const double> values, double low, double high,
                                  ColorMap map);

}  // namespace curvefold
