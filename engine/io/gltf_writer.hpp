// glTF 2.0 binary (.glb) export for Blender and viewers: the folded paper as a double-sided mesh
// and the creases as coloured lines.
#pragma once

#include <filesystem>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

// Writes one mesh, atomically: a TRIANGLES primitive (float POSITION, NORMAL, TEXCOORD_0 = the
// development in metres, uint32 indices, a double-sided paper material) and LINES primitives for
// the mountain (red) and valley (blue) creases. Vertices on creases are split so the normals stay
// sharp there, while bending edges stay smooth. Throws FileError when the file cannot be written.
void writeGlb(const Sheet& sheet, const std::filesystem::path& path);

}  // namespace curvefold
