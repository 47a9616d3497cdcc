// Where curvefold keeps what it carries between sessions for the user (the recent designs, a
// design rescued when its autosave could not be written): $XDG_STATE_HOME/curvefold, else
// ~/.local/state/curvefold (the XDG Base Directory specification).
#pragma once

#include <filesystem>

namespace curvefold::session {

// The folder (not created here); empty when neither XDG_STATE_HOME nor HOME is set.
std::filesystem::path stateFolder();

}  // namespace curvefold::session
