// `curvefold design` and plain `curvefold`'s window: the command's options, read into
// DesignerOptions for the window (designer.cpp).
#include <memory>

#include "app/cli/commands.hpp"
#include "app/desktop/designer.hpp"

namespace curvefold::cli {

void addDesignCommand(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("design", "Open the desktop designer window (needs a display)");
  auto options = std::make_shared<desktop::DesignerOptions>();
  command->add_option("INPUT", options->input,
                      "Design file (*.curvefold.json) or surface name (default: square)");
  addSessionFileOptions(command, options->record, options->autosave, options->target,
                        "after every committed fold");
  command->add_flag("--resume", options->resume, "Start from the autosaved design");
  command->add_flag("--crease-pattern-panel", options->creasePatternPanel,
                    "Show the crease pattern as a side view (also a checkbox in the panel)");
  command->add_option("--size", options->size, "Window size WxH (default 1280x720)");
  command
      ->add_option("--msaa", options->msaa,
                   "Samples per pixel (default: 4 on a GPU, 1 on a CPU driver such as lavapipe)")
      ->check(CLI::IsMember({1, 2, 4, 8}));
  command->add_option("--screenshot-on-exit", options->screenshotOnExit,
                      "Write the last frame's scene to this PNG when the window closes");
  command->add_option("--frame-times", options->frameTimes,
                      "Write each frame's duration (ms, one a line) to this file when the window "
                      "closes");
  command->callback([options] { desktop::runDesigner(*options); });
}

void runDefaultDesigner() {
  desktop::runDesigner(desktop::DesignerOptions{});
}

}  // namespace curvefold::cli
