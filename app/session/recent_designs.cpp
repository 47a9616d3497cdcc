#include "app/session/recent_designs.hpp"

#include "app/session/state_folder.hpp"

#include <cstdlib>
#include <fstream>
#include <limits>
#include <vector>

#include "engine/io/atomic_file.hpp"
#include "engine/text/utf8.hpp"
#include "sim_input/recording.hpp"

namespace curvefold::session {

namespace fs = std::filesystem;

fs::path recentDesignsFile() {
  const fs::path folder = stateFolder();
  return folder.empty() ? folder : folder / "recent-designs";
}

std::vector<std::string> loadRecentDesigns() {
  std::vector<std::string> recent;
  const fs::path file = recentDesignsFile();
  if (file.empty()) return recent;
  // Only a regular file (a FIFO would block the open), read a bounded line at a time: a line
  // longer than a path may be is skipped without being held (a 300 MB line once was, whole).
  std::error_code error;
  if (!fs::is_regular_file(file, error)) return recent;
  std::ifstream in(file, std::ios::binary);
  std::vector<char> line(kMaxRecentPathBytes);
  while (recent.size() < kMaxRecentDesigns) {
    in.getline(line.data(), static_cast<std::streamsize>(line.size()));
    if (in.bad() || (in.fail() && in.eof())) break;
    if (in.fail()) {  // no end of line within the bound
      in.clear();
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      continue;
    }
    const std::string path(line.data());
    // What the panel keeps (UTF-8, which a recording's JSON needs), so the list it saves agrees.
    if (!path.empty() && isUtf8(path)) recent.push_back(path);
  }
  return recent;
}

void saveRecentDesigns(const std::vector<std::string>& recent) {
  const fs::path file = recentDesignsFile();
  if (file.empty()) return;
  std::string text;
  for (std::size_t i = 0; i < recent.size() && i < kMaxRecentDesigns; ++i)
    if (recent[i].find('\n') == std::string::npos) text += recent[i] + "\n";
  std::error_code ignored;
  fs::create_directories(file.parent_path(), ignored);
  writeFileAtomically(file, text);
}

}  // namespace curvefold::session
