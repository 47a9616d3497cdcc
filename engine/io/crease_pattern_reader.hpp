// Either crease-pattern format by its name or, failing that, its first character: what a command
// that takes "any crease pattern" calls (fold_crease_pattern.hpp, svg_crease_pattern.hpp).
#pragma once

#include <filesystem>

#include "engine/io/crease_pattern.hpp"

namespace curvefold {

// .fold (any case) is FOLD, .svg is SVG; any other name is FOLD when its text starts with '{'
// (after white space) and SVG when with '<'. Throws FileError when the file cannot be read and
// CreasePatternError for everything else, "<path>: neither FOLD nor SVG" included.
CreasePattern readCreasePattern(const std::filesystem::path& path);

}  // namespace curvefold
