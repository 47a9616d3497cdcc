// The desktop designer window (docs/design.md 5 and 7): what `curvefold design` and plain
// `curvefold` open. The command's options are read in app/cli/design_command.cpp; the window is
// designer.cpp.
#pragma once

#include <string>

namespace curvefold::desktop {

struct DesignerOptions {
  std::string input;  // design file, surface name, or empty for the default surface
  std::string record, autosave, screenshotOnExit, size = "1280x720";
  std::string target;      // a target shape (OBJ) to fold toward
  std::string frameTimes;  // where to write each frame's duration when the window closes
  bool resume = false;
  bool validation = false;
  bool creasePatternPanel = false;
  int msaa = 0;  // samples per pixel; 0: the device's interactive default
};

// Opens the window and runs it until it closes; throws cli::NoDisplayError without a display,
// cli::UsageError for bad options, and the first problem saving the session's files.
void runDesigner(const DesignerOptions& options);

}  // namespace curvefold::desktop
