// Synthetic gestures: hand motion made from a few intentions ("turn the sheet 30 degrees",
// "grab the point nearest P and drag it to Q", "undo"), for tests and example recordings. The
// generator runs the interaction core on the frames it makes, so a gesture can refer to the sheet
// as it is at that moment; what comes out is an ordinary recording.
//
// Gesture script (JSON):
//   {"format":"curvefold-gesture-script","version":1,
//    "source":"script",                 // optional: "script" (default), "desktop" or "synthetic"
//    "rate":60,                         // frames per second (optional, default 90)
//    "handedness":"right",              // optional
//    "surface":{...as in a design document...},
//    "symmetry":"rotational:6:y",       // optional: every fold brings its images (symmetry.hpp)
//    "sheet_frame":{"position":[x,y,z],"orientation":[w,x,y,z]},  // optional
//    "gestures":[
//      {"wait":0.3},                                           // seconds, hands still
//      {"turn_sheet":{"axis":[0,1,0],"degrees":30,"duration":0.5}},
//      {"move_sheet":{"by":[x,y,z],"duration":0.5}},           // world metres
//      {"scale_sheet":{"by":1.5,"duration":0.8}},               // both hands; view scale
//      {"sheet_hand":{"to":{"position":[x,y,z],"orientation":[w,x,y,z]},"duration":0.5,
//                     "clutch":true}},                         // world pose; clutch optional
//      {"drag":{"grab":[x,y,z],"to":[x,y,z],"via":[[x,y,z]],"duration":1.0,
//               "turn_sheet":{"axis":[1,0,0],"degrees":20}}},  // sheet points; turn optional;
//                                              // while simulating (studio), a pull, not a fold
//      {"undo":{}}, {"redo":{}}, {"cancel":{}}, {"switch_hands":{}},  // "hold":0.12 optional
//      {"point_at":{"item":"Create","click":true,"duration":0.5,"hold":0.12}},  // studio: an item
//      {"toggle_panel":{}}]}                                          // studio: show or hide it
// A press or click is held "hold" seconds (default kClickSeconds, a person's click); one held
// under kShortestSeenClickSeconds is recorded with a warning, as a real runtime may miss it.
// A script with "studio":{} (optionally {"recent":[paths]}) is a headset session with its panel:
// the point hand then has an aim (its ray), and point_at points it at a panel item by the item's
// label, so a script survives a change of the panel's layout.
// "grab" is a point near the sheet in sheet coordinates: the nearest surface point is grabbed.
// "to" and "via" are where that point is dragged, in sheet coordinates of the sheet frame at the
// start of the drag; a "turn_sheet" inside a drag turns the sheet with the other hand meanwhile,
// so the fold follows both hands. Turns pivot about the sheet's centre.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "engine/geometry/fold_session.hpp"
#include "interaction/interaction_core.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {

// Limits that bound what a script may cost (far above what a test or an example needs).
inline constexpr double kMaxGestureRate = 1000.0;            // frames per second
inline constexpr double kMaxGestureSeconds = 600.0;          // one gesture's duration, one wait
inline constexpr std::size_t kMaxGestureFrames = 1'000'000;  // a whole script
inline constexpr std::uint64_t kMaxGestureScriptBytes = 16ull << 20;
// A person's click holds the button about a tenth of a second or more. A runtime reports a button's
// state at each sync, so a press it should see must last two frames at 20 frames a second: 100 ms.
inline constexpr double kClickSeconds = 0.12;
inline constexpr double kShortestSeenClickSeconds = 0.1;
inline constexpr double kMaxClickSeconds = 10.0;  // "hold" above this is refused as a mistake

class GestureError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SheetTurn {
  glm::dvec3 axis{0.0, 1.0, 0.0};  // world
  double degrees = 0.0;
};

// What a script's frames act on: by default the interaction core over a fold session; a studio
// script (its header has "studio") acts on the headset's studio, whose panel a gesture can point
// at by an item's label. The app provides that one (it needs Dear ImGui).
class GestureWorld {
 public:
  virtual ~GestureWorld() = default;
  virtual void process(const InputFrame& frame) = 0;
  // The core now (a panel's new sheet replaces it).
  virtual const InteractionCore& core() const = 0;
  // The world position of the panel item with this label, when the panel shows it.
  virtual std::optional<glm::dvec3> panelItem(const std::string& label) const {
    (void)label;
    return std::nullopt;
  }
  // The panel's front (world), for a hand to point at it from there.
  virtual std::optional<glm::dvec3> panelFacing() const { return std::nullopt; }
};
using GestureWorldFactory = std::function<std::unique_ptr<GestureWorld>(const RecordingHeader&)>;

class GestureRecorder {
 public:
  // Where frames go as they are made instead of into recording().frames (a script streamed to a
  // file holds no frames in memory).
  using FrameSink = std::function<void(const InputFrame&)>;

  // maxFrames bounds the recording (a fuzzer bounds it lower).
  // world: makes what a studio script's frames act on (a script without "studio" acts on the core
  // over a fold session); a studio header needs one.
  explicit GestureRecorder(RecordingHeader header, std::size_t maxFrames = kMaxGestureFrames,
                           FrameSink sink = nullptr, const GestureWorldFactory& world = nullptr);

  void wait(double seconds);
  // Clutch, turn the sheet about its centre (world axis), release.
  void turnSheet(const SheetTurn& turn, double seconds);
  // Clutch, move the sheet by a world offset, release.
  void moveSheet(const glm::dvec3& by, double seconds);
  // Both hands take the sheet (the point hand beside the sheet hand, both squeezes), spread or
  // close until the view scale is `factor` times what it was, and let go.
  void scaleSheet(double factor, double seconds);
  // Move the non-dominant hand to a world pose over `seconds` (position interpolated, orientation
  // slerped), the sheet following when `clutch` is squeezed: "clutch at pose A, move to pose B".
  void moveSheetHand(const Pose& to, double seconds, bool clutch);
  // Approach the surface point nearest `grabNear` (sheet coordinates), pull the trigger, drag it
  // through `path` (sheet coordinates of the frame at the start) over `seconds`, optionally
  // turning the sheet with the other hand meanwhile, and release. Throws GestureError when the
  // grab does not take (the point is out of reach).
  void drag(const glm::dvec3& grabNear, const std::vector<glm::dvec3>& path, double seconds,
            const std::optional<SheetTurn>& turnDuring = std::nullopt);
  // Press `button` for `holdSeconds` (at least one frame) and release it.
  void press(Button button, double holdSeconds = kClickSeconds);
  // Studio: point the dominant hand's ray at the panel item with this label (from 20 cm in front
  // of the panel) over `seconds`, and click it with the trigger (held `holdSeconds`) when `click`.
  // Throws GestureError when no such item is shown.
  void pointAt(const std::string& label, double seconds, bool click,
               double holdSeconds = kClickSeconds);

  // The header and, without a sink, the frames.
  const Recording& recording() const { return recording_; }
  std::size_t frameCount() const { return frameCount_; }
  // Seconds from the first frame to the last.
  double duration() const { return frameCount_ > 1 ? double(frameCount_ - 1) * dt_ : 0.0; }
  const FoldSession& session() const { return world_->core().session(); }
  const InteractionCore& core() const { return world_->core(); }

 private:
  // The frames `seconds` takes at the header's rate (at least 1); throws GestureError when they
  // would take the recording past kMaxGestureFrames.
  int stepsFor(double seconds) const;
  // Appends one frame and runs the core on it.
  void step();
  // The sheet hand pose that turns the sheet by `turn` (scaled by `fraction`) about its centre.
  Pose turnedHand(const Pose& start, const Pose& sheetAtStart, const SheetTurn& turn,
                  double fraction) const;

  // The centre of the sheet's bounding box (sheet coordinates), of the session now.
  glm::dvec3 sheetCentre();
  // A headset's point hand aims down at the paper between panel gestures, its ray clear of the
  // panel (a script without a panel records no aim).
  void aimAtPaper();

  Recording recording_;
  FrameSink sink_;
  std::size_t frameCount_ = 0;
  std::unique_ptr<GestureWorld> world_;
  InputFrame frame_;
  const FoldSession* centreOf_ = nullptr;
  glm::dvec3 sheetCentre_{0.0};
  double dt_ = 1.0 / 90.0;
  std::size_t maxFrames_;
};

// Runs a gesture script (the format above) into a recording. Throws GestureError naming the file
// and the gesture for anything wrong with the script.
Recording recordGestureScript(const std::filesystem::path& script,
                              const GestureWorldFactory& world = nullptr);
// The same from the script's text (nameForErrors starts every message), with at most maxFrames.
Recording recordGestureScriptText(std::string_view text, std::string_view nameForErrors,
                                  std::size_t maxFrames = kMaxGestureFrames,
                                  const GestureWorldFactory& world = nullptr);

// Streams a script's recording: `header` once the script's header is read, then every frame as
// it is made, none held in memory. Returns the frame count and their duration in seconds.
struct GestureStream {
  std::size_t frames = 0;
  double seconds = 0.0;
  // What was recorded but may not play as meant: one line each, naming the gesture.
  std::vector<std::string> warnings;
};
GestureStream streamGestureScript(const std::filesystem::path& script,
                                  const std::function<void(const RecordingHeader&)>& header,
                                  const GestureRecorder::FrameSink& frame,
                                  const GestureWorldFactory& world = nullptr);

}  // namespace curvefold
