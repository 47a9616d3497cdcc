// Recorded input (docs/design.md 6): a session's input frames as JSON Lines, so that any session (a
// headset, the desktop, a gesture script) can be replayed bit for bit without its source.
//
// Line 1 is the header:
//   {"format":"curvefold-recording","version":2,"source":"openxr","handedness":"right",
//    "units":"m","rate":90,"sheet_frame":{"position":[x,y,z],"orientation":[w,x,y,z]},
//    "surface":{...the "surface" object of a design document...}}
// then one frame per line:
//   {"t":0.011,"sheet":{"position":[x,y,z],"orientation":[w,x,y,z],"tracked":true,"clutch":0.0},
//    "point":{"position":[x,y,z],"tracked":true,"select":0.0},"buttons":["undo"]}
// "point" may also hold "grip" (0..1, the squeeze), "aim" ([w,x,y,z]: the ray the point hand
// casts at the headset's panel, from the tip along the orientation's -Z) and "scroll" (-1..1, the
// thumbstick); each is written only when there is one. A header with "studio" is a headset session
// with its panel ({"recent":[paths]}: the recent designs it listed), replayed with the panel.
// "symmetry" ("rotational:6:y", "mirror:x"): every fold brings its images, in the replay too.
// "source" says where the frames came from: "openxr" (controllers), "hands" (an OpenXR session
// bare hands began), "desktop", "script" or "synthetic"; the frames are the same either way.
// "suggestions" ([{"seed":[u,v],"grab":[x,y,z],"to":[x,y,z]}], best first) are the studio's
// suggested folds that arrived in that frame (docs/design.md 9), so a replay offers the same ones.
// "simulation" ({"percent":P,"steps":N,"pull":{"vertex":i,"to":[x,y,z]}}, version 2) is present
// while the sheet is simulated (InputFrame::simulation): the fold amount (0..100), the dynamic
// steps the frame takes, and the vertex a hand pulls toward `to` (sheet coordinates), if any;
// "solver":"gpu" when the Vulkan compute solver stepped it (absent: the CPU's). A Player refuses
// a recording with GPU frames (float, bit for bit only on the device that ran it).
// "buttons" lists what is held and is omitted when nothing is. Every double is written in its
// shortest exact form, so parsing a line gives back the very bits that were written.
#pragma once

#include <cstddef>
#include <filesystem>
#include <istream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/io/design_document.hpp"
#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"

namespace curvefold {

inline constexpr std::string_view kRecordingFormat = "curvefold-recording";
// Version 2 added "simulation" (issue 39); version 1 files read as ever (they have none).
inline constexpr int kRecordingVersion = 2;
inline constexpr int kOldestRecordingVersion = 1;

// A quaternion whose length is further than this from 1 is refused rather than normalised, so
// that replay sees exactly the recorded bits. OpenXR's float poses stay well within it.
inline constexpr double kQuaternionUnitTolerance = 1e-6;

// The most recent designs a studio session lists, and the longest path it keeps of one.
inline constexpr std::size_t kMaxRecentDesigns = 8;
inline constexpr std::size_t kMaxRecentPathBytes = 4096;

// One line naming the file and the line, e.g. "a.jsonl: line 7: sheet.clutch: must lie in [0, 1]".
// line() is 0 for a problem that is not on a line (a file that cannot be read).
class RecordingError : public std::runtime_error {
 public:
  RecordingError(const std::string& message, std::size_t line = 0)
      : std::runtime_error(message), line_(line) {}
  std::size_t line() const { return line_; }

 private:
  std::size_t line_;
};

// Where the frames came from; informative, but only these are written and read.
inline constexpr std::string_view kRecordingSources[] = {"synthetic", "script", "desktop", "openxr",
                                                         "hands"};

struct RecordingHeader {
  std::string source = "synthetic";
  HandSide handedness = HandSide::Right;  // the dominant hand
  Pose sheetFrame;                        // the initial world_from_sheet
  InitialSurface surface;
  double rate = 90.0;  // nominal frames per second (informative)
  // A headset session with its panel: replayed with the panel running (without drawing), so the
  // panel's actions (a new sheet, undo, ...) replay too. `recent` is the panel's list of recent
  // designs when the session started, so the replay lists the same ones.
  struct Studio {
    std::vector<std::string> recent;
    bool operator==(const Studio&) const = default;
  };
  std::optional<Studio> studio;
  // The design's symmetry (engine/geometry/symmetry.hpp), so a replay folds the images too;
  // empty: none.
  std::string symmetry;
};

struct Recording {
  RecordingHeader header;
  std::vector<InputFrame> frames;
  bool truncated = false;     // the file ended inside a line, which was dropped
  std::size_t lineCount = 0;  // whole lines read, the header included
};

struct ReadOptions {
  // Keep the whole frames of a file whose last line was cut off, instead of refusing it.
  bool allowTruncated = false;
};

// Reads and checks a recording: every value finite, quaternions unit, clutch and select in
// [0, 1], time never going backwards, and an initial surface the engine builds. Throws
// RecordingError (one line naming the file and the line) for anything wrong, including a cut-off
// last line ("truncated at line N") unless options.allowTruncated.
Recording readRecording(const std::filesystem::path& path, const ReadOptions& options = {});
Recording parseRecording(std::istream& in, std::string_view nameForErrors,
                         const ReadOptions& options = {});

// One line of the file, without its newline. Both throw RecordingError for what the reader would
// refuse (a value that is not finite, a non-unit quaternion, an unknown source, ...), so that no
// unreadable line is ever written.
std::string headerLine(const RecordingHeader& header);
std::string frameLine(const InputFrame& frame);

// Writes a whole recording atomically (a recording made in memory, like a gesture script's; a live
// session uses Recorder). Throws RecordingError for a line the reader would refuse, FileError when
// the file cannot be written.
void writeRecording(const Recording& recording, const std::filesystem::path& path);

// The button names used in the file ("cancel", "undo", "redo", "switch_hands", "panel",
// "take_suggestion", "next_suggestion").
std::string_view buttonName(Button button);

}  // namespace curvefold
