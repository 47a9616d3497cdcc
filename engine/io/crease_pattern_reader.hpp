// Either crease-pattern format by its name or, failing that, its first character: what a command
// that takes "any crease pattern" calls (fold_crease_pattern.hpp, svg_crease_pattern.hpp).
#pragma once

#include <filesystem>

#include "engine/io/crease_pattern.hpp"

namespace curvefold {

// .fold (any case) is FOLD, .svg is SVG; any other name is FOLD when its text starts with '{'
// (after white space) and SVG when with '<'. Throws FileError when the file cannot be read and
// CreasePatternError for everything else, "<path>: neither FOLD nor SVG" included. The vertices
// are in metres (scaleToMetres below): an SVG's by its width and height (svg_crease_pattern.hpp),
// a FOLD file's by its frame_unit, else as metres (fold_crease_pattern.cpp).
CreasePattern readCreasePattern(const std::filesystem::path& path);

// Multiplies the vertices by pattern.metresPerUnit, which is then 1.
void scaleToMetres(CreasePattern& pattern);

// Scales the vertices about the origin so the larger side of their bounding box is largerSide
// (a pattern whose file states no size, or one printed at another size).
void scaleToSize(CreasePattern& pattern, double largerSide);

// A larger side given in millimetres (`simulate --size`, Python's simulate(size=)), checked and in
// metres for scaleToSize. Throws std::invalid_argument "size: must be above 0 and at most 1000000
// mm (1 km)" (the caller prefixes it as it names the value).
double sheetSizeMetres(double sizeMm);

}  // namespace curvefold
