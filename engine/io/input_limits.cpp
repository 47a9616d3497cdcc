#include "engine/io/input_limits.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <new>
#include <optional>

#include "engine/io/atomic_file.hpp"
#include "engine/text/input_path.hpp"

namespace curvefold {

std::string tooLarge(std::string_view name, std::uint64_t bytes, std::uint64_t maxBytes,
                     std::string_view kind) {
  return std::string(name) + ": " + (bytes > 0 ? std::to_string(bytes) + " bytes, more" : "more") +
         " than a " + std::string(kind) + " may hold (" + std::to_string(maxBytes >> 20) + " MiB)";
}

std::string readWholeFile(const std::filesystem::path& path, std::uint64_t maxBytes,
                          std::string_view kind) {
  const std::string name = path.string();
  // Only a regular file: a FIFO would block the open, a device might never end.
  if (const std::optional<std::string> why = notRegularFile(path))
    throw FileError("cannot read " + name + ": " + *why);
  std::error_code error;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError("cannot read " + name + ": " + std::strerror(errno));
  // The size up front (the bound below still holds for a file that grows while read).
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > maxBytes) throw FileError(tooLarge(name, size, maxBytes, kind));
  try {
    std::string text;
    if (size > 0) text.reserve(size);
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
      text.append(buffer, static_cast<std::size_t>(in.gcount()));
      if (text.size() > maxBytes) throw FileError(tooLarge(name, 0, maxBytes, kind));
    }
    if (in.bad()) throw FileError("cannot read " + name + ": read error");
    return text;
  } catch (const std::bad_alloc&) {
    throw FileError(name + ": out of memory reading it");
  }
}

}  // namespace curvefold
