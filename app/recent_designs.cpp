#include "app/recent_designs.hpp"

#include <cstdlib>
#include <fstream>

#include "engine/io/atomic_file.hpp"
#include "sim_input/recording.hpp"

namespace curvefold::cli {

namespace fs = std::filesystem;

fs::path recentDesignsFile() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state)
    return fs::path(state) / "curvefold" / "recent-designs";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".local" / "state" / "curvefold" / "recent-designs";
  return {};
}

std::vector<std::string> loadRecentDesigns() {
  std::vector<std::string> recent;
  const fs::path file = recentDesignsFile();
  if (file.empty()) return recent;
  std::ifstream in(file);
  for (std::string line; recent.size() < kMaxRecentDesigns && std::getline(in, line);)
    if (!line.empty() && line.size() < 4096) recent.push_back(line);
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

}  // namespace curvefold::cli
