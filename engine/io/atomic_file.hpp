// Writing a file so that readers see either the old content or the whole new one, never a
// half-written file: the content goes to a temporary file in the same directory (so the rename
// stays on one file system), is flushed to disk, then renamed over the target.
//
// Only a regular file (or no file) is replaced by rename, keeping its permissions. A symbolic
// link is followed, so the file it names is replaced and the link stays. A device or a FIFO is
// written in place (there is nothing to rename over /dev/null), with its write errors reported
// (/dev/full says "No space left on device"). "-" is standard output.
//
// Temporaries are named ".NAME.tmp-PID-N" (and a set of outputs stages ".NAME.staged-PID"); a
// write to NAME removes those left behind by processes that are gone (killed mid-write).
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

// Where a write to path lands: symbolic links followed (up to 40, then FileError ELOOP).
std::filesystem::path resolveOutputPath(const std::filesystem::path& path);
// True for "-" and for an existing file that is not a regular file or a directory (a device, a
// FIFO, a socket): written in place, never replaced.
bool writesInPlace(const std::filesystem::path& resolvedPath);
// The hidden name a set of outputs stages `resolvedPath` under before renaming it into place.
std::filesystem::path stagingPathFor(const std::filesystem::path& resolvedPath);
// Gives `staged` the permission bits of an existing regular `target` (so a rename over it keeps
// them); nothing when target does not exist.
void keepPermissions(const std::filesystem::path& target, const std::filesystem::path& staged);
// Removes ".NAME.tmp-PID-N" and ".NAME.staged-PID" files (and staged folders, as a replay's
// frames are staged) next to resolvedPath whose process is gone. Called by every write; the
// directory is listed once per process.
void removeStaleTemporaries(const std::filesystem::path& resolvedPath);

}  // namespace curvefold
