// The crease pattern for laser cutters and cutting plotters (issue 18, 2; docs/design.md 4): real
// millimetres, hairline strokes, one Inkscape layer each for the cut (boundary, slits, holes), the
// mountain scores and the valley scores, in a colour per layer that the machines' software maps
// to an operation (LightBurn layers, Glowforge steps, a plotter's pens; colours.hpp says why these
// are not the paper colours). Lines are joined into
// polylines, so a machine follows a crease without lifting. Perforation turns the scores into
// cuts of a given length with gaps between, for folding by hand without a scoring tool; being
// cuts, they get a layer of their own.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct Perforation {
  double cutMm = 0.0;  // each cut
  double gapMm = 0.0;  // paper left between cuts
};

// No cutter cuts finer than this, and no file holds more dashes than this (a million dashes is
// about 80 MB of SVG): both are checked before anything is made.
inline constexpr double kMinPerforationMm = 0.1;
inline constexpr double kMaxPerforationDashes = 1e6;

// One layer: its name, its colour ("#rrggbb") and its polylines (millimetres, y down).
struct CutterLayer {
  std::string name;
  std::string colour;
  std::vector<std::vector<glm::dvec2>> polylines;
};

// The layers in order: "cut" red, "mountain score" blue, "valley score" green, and with
// perforation a fourth, "perforation" magenta, that holds the dashes of every crease (each dash a
// polyline along its crease; the pattern runs on along a whole crease, only its last dash
// shorter), leaving the score layers empty.
std::vector<CutterLayer> cutterLayers(const Sheet& sheet,
                                      const std::optional<Perforation>& perforation = {});

// Writes them as SVG, atomically. Throws std::invalid_argument for a perforation whose cut or gap
// is under kMinPerforationMm (or not finite) or that would make more than kMaxPerforationDashes
// dashes, FileError when the file cannot be written.
void writeCutterSvg(const Sheet& sheet, const std::filesystem::path& path,
                    const std::optional<Perforation>& perforation = {});

// The stroke width: a hairline (0.01 mm), which cutters read as "follow this line" rather than
// "engrave this area".
inline constexpr double kHairlineMm = 0.01;

}  // namespace curvefold
