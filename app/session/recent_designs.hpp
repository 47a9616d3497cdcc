// The designs a user saved or opened lately, newest first, kept between sessions in
// $XDG_STATE_HOME/curvefold/recent-designs (default ~/.local/state), one path per line, for the
// studio panel's "Recent designs".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace curvefold::session {

// Where the list lives; empty when neither XDG_STATE_HOME nor HOME is set.
std::filesystem::path recentDesignsFile();

// The list (at most kMaxRecentDesigns); empty when there is none or it cannot be read.
std::vector<std::string> loadRecentDesigns();
// Replaces the list atomically; throws FileError when it cannot be written.
void saveRecentDesigns(const std::vector<std::string>& recent);

}  // namespace curvefold::session
