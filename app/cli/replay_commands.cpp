// `replay` and `record-script`: recorded input (docs/design.md 6) on the command line.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/commands.hpp"
#include "app/studio/studio_replay.hpp"
#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/io/output_set.hpp"
#include "sim_input/gestures.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"

namespace curvefold::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string seconds(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g s", value);
  return buffer;
}

// A one-line bar on stderr, only when stderr is a terminal and the replay has run (or will run,
// in real time) longer than a second; redrawn at most ten times a second.
class ProgressBar {
 public:
  explicit ProgressBar(bool realtime, double duration)
      : enabled_(::isatty(STDERR_FILENO) == 1), start_(Clock::now()) {
    if (realtime && duration > 1.0) shown_ = enabled_;
  }
  ~ProgressBar() { clear(); }

  void update(const ReplayProgress& progress) {
    if (!enabled_) return;
    const Clock::time_point now = Clock::now();
    if (!shown_) {
      if (now - start_ < std::chrono::seconds(1)) return;
      shown_ = true;
    } else if (now - lastDraw_ < std::chrono::milliseconds(100)) {
      return;
    }
    lastDraw_ = now;
    const double fraction =
        progress.frameCount == 0 ? 1.0 : double(progress.frame) / double(progress.frameCount);
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::string bar =
        "\rreplaying [" + std::string(filled, '#') + std::string(kWidth - filled, ' ') + "] ";
    char numbers[64];
    std::snprintf(numbers, sizeof numbers, "%3.0f%%  %.1f/%.1f s", 100.0 * fraction, progress.time,
                  progress.duration);
    std::cerr << bar << numbers << std::flush;
  }

  void clear() {
    if (!shown_) return;
    std::cerr << "\r" << std::string(60, ' ') << "\r" << std::flush;
    shown_ = false;
  }

 private:
  bool enabled_;
  bool shown_ = false;
  Clock::time_point start_;
  Clock::time_point lastDraw_{};
};

}  // namespace

void addReplayCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "replay", "Replay a recording into a design, FOLD, SVG, OBJ and a per-fold log");
  struct Options {
    std::string recording, out;
    bool realtime = false;
    bool allowTruncated = false;
    std::string frames, framesSize = "1280x720";
    std::size_t every = 1;
    bool panel = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("REC", options->recording, "Recording (JSON Lines, *.jsonl)")->required();
  command->add_option("--out", options->out,
                      "Folder for the output files (default: the recording's name without its "
                      "extension, in the current folder)");
  command->add_flag("--realtime", options->realtime, "Replay at the recorded pace");
  command->add_flag("--allow-truncated", options->allowTruncated,
                    "Replay a cut-off recording up to its last whole frame (with a warning)");
  command->add_option("--frames", options->frames,
                      "Also render the session to DIR/frame_NNNNNN.png (headless Vulkan)");
  command->add_option("--every", options->every, "With --frames: one PNG every N frames");
  command->add_option("--size", options->framesSize, "With --frames: image size WxH");
  command->add_flag("--crease-pattern-panel", options->panel,
                    "With --frames: show the 2D crease pattern at the right");
  command->callback([options] {
    // The renderer comes first: without Vulkan, fail before writing anything.
    std::shared_ptr<ReplayFrameWriter> frameWriter;
    if (!options->frames.empty())
      frameWriter = makeReplayFrameWriter(options->frames, options->every, options->framesSize,
                                          options->panel);
    const fs::path recordingPath = options->recording;
    const Recording recording = readRecording(recordingPath, {options->allowTruncated});
    const std::string name = recordingPath.stem().string();
    const fs::path dir = options->out.empty() ? fs::path(name) : fs::path(options->out);

    ReplayOptions replayOptions;
    replayOptions.realtime = options->realtime;
    const double duration = recording.frames.empty()
                                ? 0.0
                                : recording.frames.back().time - recording.frames.front().time;
    ProgressBar bar(options->realtime, duration);
    replayOptions.onFrame = [&bar](const ReplayProgress& progress) { bar.update(progress); };
    const Clock::time_point start = Clock::now();
    const ReplayResult result = studio::replayAnyRecording(recording, replayOptions);
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    bar.clear();

    std::string log;
    for (const FoldLogEntry& entry : result.log) log += foldLogLine(entry) + "\n";
    OutputSet outputs;
    outputs.add(dir / (name + ".curvefold.json"),
                [&](const fs::path& path) { saveDesign(result.design, path); });
    outputs.add(dir / (name + ".fold"),
                [&](const fs::path& path) { writeFold(result.sheet, path); });
    outputs.add(dir / (name + ".svg"),
                [&](const fs::path& path) { writeSvgCreasePattern(result.sheet, path); });
    outputs.add(dir / (name + ".obj"), [&](const fs::path& path) { writeObj(result.sheet, path); });
    outputs.add(dir / (name + ".folds.jsonl"),
                [&](const fs::path& path) { writeFileAtomically(path, log); });
    refuseOutputsOverInputs(
        {dir / (name + ".curvefold.json"), dir / (name + ".fold"), dir / (name + ".svg"),
         dir / (name + ".obj"), dir / (name + ".folds.jsonl")},
        {{recordingPath, "the recording being replayed"}});
    // The frames first, into their staging folder: if they fail, no output has changed.
    std::size_t framesWritten = 0;
    if (frameWriter) framesWritten = writeReplayFrames(*frameWriter, recording);
    outputs.write(dir);
    if (frameWriter) commitReplayFrames(*frameWriter);

    if (recording.truncated)
      std::cerr << "curvefold: warning: " << recordingPath.string() << ": truncated at line "
                << recording.lineCount + 1 << "; replayed the " << recording.frames.size()
                << " whole frames before it\n";
    std::cout << "replayed " << recordingPath.string() << ": " << result.frameCount << " frames ("
              << seconds(result.duration) << "), " << result.design.folds.size()
              << (result.design.folds.size() == 1 ? " fold, " : " folds, ")
              << result.sheet.triangleCount() << " triangles, in " << seconds(elapsed)
              << (result.endedWhileDragging ? " (a drag left unfinished)" : "") << "; wrote "
              << (dir / (name + ".*")).string() << "\n";
    if (frameWriter)
      std::cout << "wrote " << framesWritten << " frames to " << options->frames << "\n";
  });
}

void addRecordScriptCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand("record-script", "Turn a gesture script into a recording");
  struct Options {
    std::string script, output;
  };
  auto options = std::make_shared<Options>();
  command->add_option("SCRIPT", options->script, "Gesture script (JSON)")->required();
  command->add_option("-o,--output", options->output, "Recording to write (*.jsonl)")->required();
  command->callback([options] {
    refuseOutputsOverInputs({options->output}, {{options->script, "the script itself"}});
    // Streamed: each frame is written as the script makes it, into the staged file, which
    // replaces the output only once the whole script has run. Standard output or a device has
    // no staged file: the script is run once with nothing written, so a bad one writes nothing.
    GestureStream stream;
    if (writesInPlace(resolveOutputPath(options->output)))
      streamGestureScript(
          options->script, [](const RecordingHeader&) {}, [](const InputFrame&) {},
          studio::studioGestureWorld());
    writeFileAtomically(options->output, [&](std::ostream& out) {
      stream = streamGestureScript(
          options->script,
          [&](const RecordingHeader& header) { out << headerLine(header) << '\n'; },
          [&](const InputFrame& frame) { out << frameLine(frame) << '\n'; },
          studio::studioGestureWorld());
    });
    for (const std::string& warning : stream.warnings)
      std::cerr << "curvefold: warning: " << options->script << ": " << warning << '\n';
    statusFor({options->output}) << "wrote " << options->output << " (" << stream.frames
                                 << " frames, " << seconds(stream.seconds) << ")\n";
  });
}

}  // namespace curvefold::cli
