// What an input path names, asked the same way by every reader and command.
//
// Inputs are read only from regular files: a FIFO named as an input would block the open (or the
// read) forever, a device may never end, and a folder fails deep inside the stream with a message
// naming no file. The check follows symbolic links; a missing file passes, so that the open
// itself says "No such file or directory". The standard library only, so every reader (the
// geometry core's OBJ reader too) asks the same question and words the answer the same way.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace curvefold {

// Why `path` is not a regular file to read ("it is a folder", "it is a FIFO (named pipe), not a
// regular file", ...), or nothing when it is one or does not exist.
std::optional<std::string> notRegularFile(const std::filesystem::path& path);

// Whether the file name ends in `extension` (".obj", ".jsonl"), in any case: "SCAN.OBJ" is an OBJ.
bool hasExtension(const std::filesystem::path& path, std::string_view extension);

}  // namespace curvefold
