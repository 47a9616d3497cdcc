// Writing a file so that readers see either the old content or the whole new one, never a
// half-written file: the content goes to a temporary file in the same directory (so the rename
// stays on one file system), is flushed to disk, then renamed over the target.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string_view>

namespace curvefold {

// One line naming the path and the OS reason: "cannot write /x/y.svg: No such file or directory".
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Calls writer on a stream into a temporary file next to path, fsyncs it and renames it over path.
// On failure the temporary file is removed and the target is left as it was: I/O failures throw
// FileError, an exception thrown by writer itself is rethrown unchanged.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& writer);
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);

}  // namespace curvefold
