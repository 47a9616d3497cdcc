// The legend of a quantity coloured on the sheet (color_map.hpp): a colour bar with the numbers
// at its ends and middle, the unit and a title, drawn with Cairo (as the PDF's cover text is) into
// a strip at the right of a rendered picture, so a PNG says what its colours mean.
//
// Known limits: the strip covers whatever the picture had there (a scene framed by frameBounds
// leaves the sides of a wide picture empty; a square one may lose a little of the sheet); a
// picture narrower than 120 or lower than 80 pixels gets no legend.
#pragma once

#include <string>

#include "engine/render/color_map.hpp"
#include "engine/render/image.hpp"

namespace curvefold {

struct ColorLegend {
  ColorMap map = ColorMap::Viridis;
  double low = 0.0, high = 1.0;  // the values at the bar's bottom and top
  std::string title;             // "distance to the target"
  std::string unit;              // "mm", "%", "degrees"
};

// Draws the legend into the picture's right strip, over what is there.
void drawColorLegend(RgbaImage& image, const ColorLegend& legend);

// How many pixels wide the strip is for a picture this wide.
std::uint32_t legendWidth(std::uint32_t imageWidth);

}  // namespace curvefold
