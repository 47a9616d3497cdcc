// The crease pattern as SVG for printing at real size (docs/design.md 4), in the colours Origami
// Simulator imports: boundary black, mountain red, valley blue, slit/cut green (colours.hpp);
// bending edges are not drawn.
#pragma once

#include <filesystem>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct SvgOptions {
  double marginMm = 10.0;      // blank paper around the pattern
  double strokeWidthMm = 0.2;  // hairline that still prints
};

// Writes the development's crease pattern, atomically. Throws FileError when the file cannot be
// written, std::invalid_argument for a negative margin or a non-positive stroke width.
void writeSvgCreasePattern(const Sheet& sheet, const std::filesystem::path& path,
                           const SvgOptions& options = {});

}  // namespace curvefold
