// The desktop designer window (docs/design.md 5 and 7): what `curvefold design` and plain
// `curvefold` open. The command's options are read in app/cli/design_command.cpp; the window is
// designer.cpp.
#pragma once

#include <stdexcept>
#include <string>

namespace curvefold::desktop {

struct DesignerOptions {
  std::string input;  // design file, surface name, or empty for the default surface
  std::string record, autosave, screenshotOnExit;
  unsigned width = 1280, height = 720;  // the window's size in pixels
  std::string target;                   // a target shape (OBJ) to fold toward
  std::string frameTimes;  // where to write each frame's duration when the window closes
  bool resume = false;
  bool validation = false;
  bool creasePatternPanel = false;
  bool gpu = false;  // the live simulation starts on the Vulkan compute solver (the panel's "GPU")
  int msaa = 0;      // samples per pixel; 0: the device's interactive default
};

// What the window cannot open without; the command words it for its user (the desktop room
// names no command or option).
class NoDisplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// `resume` and no autosave at `path`.
class NoAutosaveError : public std::runtime_error {
 public:
  explicit NoAutosaveError(const std::string& path)
      : std::runtime_error("no autosave at " + path) {}
};

// Opens the window and runs it until it closes; throws NoDisplayError without a display,
// NoAutosaveError, a bad target's error, and the first problem saving the session's files.
void runDesigner(const DesignerOptions& options);

}  // namespace curvefold::desktop
