// `curvefold xr [DESIGN|SURFACE|RECORDING] [--record REC] [--hands] [--left-handed]`, and plain
// `curvefold` choosing XR, the desktop window, or a line saying what is missing.
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/cli/commands.hpp"
#include "app/cli/interrupt_guard.hpp"
#include "app/xr/xr_app.hpp"
#include "engine/text/environment_choice.hpp"
#include "interaction/xr/xr_check.hpp"

namespace curvefold::cli {

namespace {

void runXr(const xr::XrAppOptions& options) {
  xr::XrApp app(options);
  const InterruptGuard guard;
  std::cout << "xr: running on " << (options.headless ? "a headless session of " : "")
            << "the OpenXR runtime \"" << app.runtimeName() << "\"" << std::endl;
  const xr::XrAppSummary summary = app.run(InterruptGuard::flag());
  std::cout << "xr: " << summary.framesProcessed << " input frames, " << summary.framesRendered
            << " frames drawn, " << summary.sessions << " session(s), " << summary.folds
            << " folds; design saved to " << summary.autosave << "\n";
  std::cout << "xr: session states:";
  for (const std::string& state : summary.states) std::cout << ' ' << state;
  std::cout << "\nxr: interaction profiles: left "
            << (summary.profiles[0].empty() ? "none" : summary.profiles[0]) << ", right "
            << (summary.profiles[1].empty() ? "none" : summary.profiles[1]) << "\n";
  if (summary.handFrames > 0)
    std::cout << "xr: bare hands drove " << summary.handFrames << " of " << summary.framesProcessed
              << " input frames\n";
  if (summary.interrupted) std::cout << "xr: interrupted; the session was ended cleanly\n";
  if (!summary.problems.empty())
    std::cout << "xr: " << summary.problems.size()
              << (summary.problems.size() == 1 ? " problem" : " problems")
              << " during the session (warned above), the first: " << summary.problems.front()
              << "\n";
  if (summary.instanceLost)
    throw XrError("the OpenXR runtime was lost (instance loss); every committed fold is saved in " +
                      summary.autosave,
                  XR_ERROR_INSTANCE_LOST);
}

}  // namespace

void addXrCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "xr",
      "Fold with tracked controllers or bare hands in an OpenXR headset (needs an OpenXR "
      "runtime)");
  auto options = std::make_shared<xr::XrAppOptions>();
  command->add_option("INPUT", options->input,
                      "Design file, surface name (default: square), or a recording (*.jsonl) "
                      "whose surface and sheet frame to start from");
  addSessionFileOptions(command, options->record, options->autosave, options->target,
                        "after every committed fold and at the end");
  command->add_option("--export-dir", options->exportDir,
                      "Folder for the panel's exports (FOLD, SVG, PDF, OBJ, glTF, PNG) and "
                      "saves (default: beside the design's autosave)");
  command->add_flag("--hands", options->hands,
                    "Fold with bare hands only (XR_EXT_hand_tracking), ignoring controllers; "
                    "without it, a hand holding no controller folds too");
  command->add_flag("--left-handed", options->leftHanded,
                    "The left hand folds and the right holds the sheet");
  command->add_flag(
      "--multiview", [options](std::int64_t) { options->multiview = xr::XrMultiview::On; },
      "Draw both eyes in one pass (VK_KHR_multiview) even on a CPU device such as lavapipe");
  command->add_flag(
      "--no-multiview", [options](std::int64_t) { options->multiview = xr::XrMultiview::Off; },
      "Draw each eye in its own pass (default: one multiview pass on a GPU that has it)");
  command->add_flag("--headless", options->headless, "Input only, nothing drawn (XR_MND_headless)");
  command->add_flag("--validation", options->validation,
                    "Enable the Vulkan validation layer; any message fails the run");
  command->callback([options] {
    xr::XrAppOptions run = *options;
    // Refused before any runtime or file is touched: exports need a folder there (or none yet).
    if (!run.exportDir.empty() && std::filesystem::exists(run.exportDir) &&
        !std::filesystem::is_directory(run.exportDir))
      throw UsageError("--export-dir " + run.exportDir + ": exists and is not a folder");
    if (vulkanValidationAsked()) run.validation = true;
    runXr(run);
  });
}

void runDefault() {
  std::string why;
  if (xrHeadsetAvailable(why)) {
    runXr(xr::XrAppOptions{});
    return;
  }
  try {
    runDefaultDesigner();
  } catch (const NoDisplayError&) {
    throw NoDisplayError("no headset for `curvefold xr` (" + why +
                         ") and no display for the designer window; use `curvefold replay` or "
                         "`curvefold render` instead");
  }
}

}  // namespace curvefold::cli
