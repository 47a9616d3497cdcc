// `curvefold design` and plain `curvefold`'s window: the command's options, read into
// DesignerOptions for the window (designer.cpp).
#include <memory>
#include <string>

#include "app/cli/commands.hpp"
#include "app/desktop/designer.hpp"
#include "engine/text/decimal.hpp"
#include "engine/text/excerpt.hpp"

namespace curvefold::cli {

namespace {

// The window, its refusals worded with the command's options and the commands to use instead.
void runWindow(const desktop::DesignerOptions& options) {
  try {
    desktop::runDesigner(options);
  } catch (const desktop::NoDisplayError& e) {
    throw NoDisplayError(std::string(e.what()) +
                         "; use `curvefold replay` or `curvefold render` instead");
  } catch (const desktop::NoAutosaveError& e) {
    throw UsageError(std::string("--resume: ") + e.what());
  }
}

}  // namespace

void addDesignCommand(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("design", "Open the desktop designer window (needs a display)");
  auto options = std::make_shared<desktop::DesignerOptions>();
  auto size = std::make_shared<std::string>("1280x720");
  command->add_option("INPUT", options->input,
                      "Design file (*.curvefold.json) or surface name (default: square)");
  addSessionFileOptions(command, options->record, options->autosave, options->target,
                        "after every committed fold");
  command->add_flag("--resume", options->resume, "Start from the autosaved design");
  command->add_flag("--crease-pattern-panel", options->creasePatternPanel,
                    "Show the crease pattern as a side view (also a checkbox in the panel)");
  command->add_option("--size", *size, "Window size WxH (default 1280x720)");
  command->add_flag("--gpu", options->gpu,
                    "Simulate live on the Vulkan compute solver (also the panel's GPU checkbox)");
  command
      ->add_option("--msaa", options->msaa,
                   "Samples per pixel (default: 4 on a GPU, 1 on a CPU driver such as lavapipe)")
      ->check(CLI::IsMember({1, 2, 4, 8}));
  command->add_option("--screenshot-on-exit", options->screenshotOnExit,
                      "Write the last frame's scene to this PNG when the window closes");
  command->add_option("--frame-times", options->frameTimes,
                      "Write each frame's duration (ms, one a line) to this file when the window "
                      "closes");
  command->callback([options, size] {
    if (!readSize(*size, 64u, 8192u, options->width, options->height))
      throw UsageError("--size: expected WxH from 64 to 8192, got " + quotedExcerpt(*size));
    runWindow(*options);
  });
}

void runDefaultDesigner() {
  runWindow(desktop::DesignerOptions{});
}

}  // namespace curvefold::cli
