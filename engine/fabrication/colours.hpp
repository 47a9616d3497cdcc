// Colours of what goes to paper and machines, in one place (README "Printing" and "Cutting").
// There are two conventions, for two readers, and they differ on purpose:
//
// - On paper (the crease-pattern SVG and the PDF), colours say what a line is: boundary black,
//   mountain red, valley blue, slit green. This is what Origami Simulator imports and what
//   origami diagrams use.
// - On a cutter (the cutter SVG), colours say what the machine does: cut red (the boundary, slits
//   and holes alike), mountain score blue, valley score green, perforation magenta. Laser and
//   plotter software maps colours to operations (LightBurn layers, Glowforge steps), red for a
//   cut as cutters do, and users set their machines up by these colours, so the cutter file keeps
//   them. Each cutter layer also carries its name, so a green valley score is not read as a slit.
#pragma once

#include "engine/geometry/creases.hpp"

namespace curvefold {

// A colour for SVG ("#rrggbb").
using SvgColour = const char*;

// On paper, for the crease-pattern SVG.
inline constexpr SvgColour paperSvgColour(Assignment assignment) {
  switch (assignment) {
    case Assignment::Mountain:
      return "#ff0000";
    case Assignment::Valley:
      return "#0000ff";
    case Assignment::Cut:
      return "#00ff00";
    default:
      return "#000000";
  }
}

// On paper, for the PDF (each channel 0 to 1): the same hues, the slit's green darker, since pure
// green prints faint on white paper.
struct PaperRgb {
  double red = 0.0, green = 0.0, blue = 0.0;
};
inline constexpr PaperRgb paperPdfColour(Assignment assignment) {
  switch (assignment) {
    case Assignment::Mountain:
      return {1.0, 0.0, 0.0};
    case Assignment::Valley:
      return {0.0, 0.0, 1.0};
    case Assignment::Cut:
      return {0.0, 0.6, 0.0};
    default:
      return {0.0, 0.0, 0.0};
  }
}

// On a cutter, by layer.
inline constexpr SvgColour kCutterCutColour = "#ff0000";
inline constexpr SvgColour kCutterMountainScoreColour = "#0000ff";
inline constexpr SvgColour kCutterValleyScoreColour = "#00ff00";
inline constexpr SvgColour kCutterPerforationColour = "#ff00ff";

}  // namespace curvefold
