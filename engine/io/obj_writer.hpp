// Wavefront OBJ export for Blender and other tools: the folded 3D mesh with the development as
// texture coordinates, and optionally the crease curves as polylines.
#pragma once

#include <filesystem>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct ObjOptions {
  bool creaseLines = true;  // crease curves as `l` polylines in a group of their own
};

// Writes `v` (3D, metres), `vt` (development, metres) and `f v/vt` with every number in its
// shortest exact form, atomically. Throws FileError when the file cannot be written.
void writeObj(const Sheet& sheet, const std::filesystem::path& path,
              const ObjOptions& options = {});

}  // namespace curvefold
