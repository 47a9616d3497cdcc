// FOLD 1.2 export (docs/design.md 4), the origami ecosystem's format (Origami Simulator, Rabbit
// Ear, ORIPA): the key frame is the crease pattern in the development, file_frames[0] the folded
// form.
#pragma once

#include <filesystem>
#include <string>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

// The FOLD file's text (one line of JSON and a newline), as writeFold writes it.
std::string foldText(const Sheet& sheet);

// Writes the sheet as a FOLD file, atomically. Throws FileError when the file cannot be written.
void writeFold(const Sheet& sheet, const std::filesystem::path& path);

}  // namespace curvefold
