#include "engine/text/input_path.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace curvefold {

namespace fs = std::filesystem;

std::optional<std::string> notRegularFile(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  switch (status.type()) {
    case fs::file_type::regular:
    case fs::file_type::not_found:
    case fs::file_type::none:  // cannot be told (no permission): the open says why
      return std::nullopt;
    case fs::file_type::directory:
      return "it is a folder, not a file";
    case fs::file_type::fifo:
      return "it is a FIFO (named pipe), not a regular file";
    case fs::file_type::character:
    case fs::file_type::block:
      return "it is a device, not a regular file";
    case fs::file_type::socket:
      return "it is a socket, not a regular file";
    default:
      return "it is not a regular file";
  }
}

bool hasExtension(const fs::path& path, std::string_view extension) {
  const std::string name = path.filename().string();
  if (name.size() <= extension.size()) return false;
  return std::equal(extension.begin(), extension.end(),
                    name.end() - std::ptrdiff_t(extension.size()), [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) ==
                             std::tolower(static_cast<unsigned char>(b));
                    });
}

}  // namespace curvefold
