#include "app/session/state_folder.hpp"

#include <cstdlib>

namespace curvefold::session {

std::filesystem::path stateFolder() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state)
    return std::filesystem::path(state) / "curvefold";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".local" / "state" / "curvefold";
  return {};
}

}  // namespace curvefold::session
