// The `curvefold` subcommands. Each registers its options on a CLI11 app and runs when chosen;
// errors are thrown as exceptions and reported by main() as one line with a non-zero exit.
#pragma once

#include <initializer_list>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace curvefold {
struct Design;
struct Recording;
struct Sheet;
struct ColorLegend;
class HeadlessRenderer;
class VulkanContext;
}  // namespace curvefold

namespace curvefold::cli {

// Thrown for a bad command line value the option parser could not catch (one line).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Ends a command with an exit status once it has said what happened (a fit interrupted by Ctrl+C
// that saved its design: 130); main prints nothing more.
class ExitStatus : public std::runtime_error {
 public:
  explicit ExitStatus(int status) : std::runtime_error("exit status"), status(status) {}
  int status;
};

// Refuses a command that names none of `outputs` (its output options):
// "COMMAND: name at least one of --a, --b, ..." in the order given.
void requireAnOutput(const std::string& command, std::initializer_list<const CLI::Option*> outputs);

// Where a command's "wrote ..." line goes: standard error when one of its outputs is standard
// output ("-"), so that what is piped is the file alone; else standard output.
std::ostream& statusFor(std::initializer_list<std::string_view> outputs);

// A surface named on a command line: a catalog name or an .obj file, its parameters (every
// surface's, as --NAME options) and a symmetry.
struct SurfaceOptions {
  std::string surface;
  std::map<std::string, double> values;
  std::string symmetry;
};
void addSurfaceOptions(CLI::App* command, SurfaceOptions& options);
// The design the options make (no folds); throws UsageError or the surface's own error.
// `sheet`, when given, receives the design's initial sheet (initialSheet(design)): the one made
// here to check the parameters, so a caller does not mesh the surface again.
Design designFromSurfaceOptions(const SurfaceOptions& options, const CLI::App* command,
                                Sheet* sheet = nullptr);

// The files a folding session (the window or the headset) records to, autosaves to and folds
// toward; `autosaveWhen` says when the session writes its autosave.
void addSessionFileOptions(CLI::App* command, std::string& record, std::string& autosave,
                           std::string& target, const std::string& autosaveWhen);

// Every number option of every command (typed INT, UINT or FLOAT) is read whole and in decimal,
// as readDecimal reads (docs/cli.md): CLI11 alone takes "0x10" as 16 and " 3" as 3. Call once,
// after every command is added.
void requireDecimalNumbers(CLI::App& app);

void addSurfacesCommand(CLI::App& app);
void addNewCommand(CLI::App& app);
void addFoldCommand(CLI::App& app);
void addExportCommand(CLI::App& app);
void addCheckCommand(CLI::App& app);
// fit_commands.cpp: folding toward a target shape, and measuring how far apart two shapes lie.
void addFitCommand(CLI::App& app);
void addDistanceCommand(CLI::App& app);
// replay_commands.cpp: recorded input.
void addReplayCommand(CLI::App& app);
void addRecordScriptCommand(CLI::App& app);
// simulate_commands.cpp: the folding simulation.
void addSimulateCommand(CLI::App& app);
// render_commands.cpp: headless Vulkan renders.
void addRenderCommand(CLI::App& app);
// A picture of a quantity coloured on a sheet (fit and distance --png, simulate --color), 1280x720
// with its legend: the renderer is made first, so a machine without Vulkan fails before any work;
// writeFieldPng renders one value per vertex and writes the PNG at `at` (an OutputSet's writer);
// fieldPng gives the PNG's bytes.
std::unique_ptr<HeadlessRenderer> makePictureRenderer();
std::string fieldPng(HeadlessRenderer& renderer, const Sheet& sheet,
                     const std::vector<double>& vertexValues, const ColorLegend& legend);
void writeFieldPng(HeadlessRenderer& renderer, const Sheet& sheet,
                   const std::vector<double>& vertexValues, const ColorLegend& legend,
                   const std::string& at);
// desktop/design_command.cpp: the desktop designer window (desktop/designer.cpp).
class NoDisplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
void addDesignCommand(CLI::App& app);
void runDefaultDesigner();  // throws NoDisplayError without a display
// xr/xr_command.cpp: `curvefold xr`, and plain `curvefold`: XR when a runtime has a headset, else
// the desktop window, else one line saying what each needs.
void addXrCommand(CLI::App& app);
void runDefault();
// `replay --frames`: made before the replay so a missing Vulkan device fails before any output.
class ReplayFrameWriter;
std::shared_ptr<ReplayFrameWriter> makeReplayFrameWriter(const std::string& dir, std::size_t every,
                                                         const std::string& size, bool panel);
// Renders the frames into a staging folder; commitReplayFrames moves them into DIR.
std::size_t writeReplayFrames(ReplayFrameWriter& writer, const Recording& recording);
void commitReplayFrames(ReplayFrameWriter& writer);

}  // namespace curvefold::cli
