// Replays a recording (docs/design.md 6): its frames go into the same interaction core as a live
// source's, over a fold session built from the header's initial surface and sheet frame, so a
// replay makes the very folds of the recorded session, bit for bit.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/io/design_document.hpp"
#include "interaction/interaction_core.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {

enum class FoldLogKind { Commit, Undo, Redo };

// One change of the committed design, for the per-fold log.
struct FoldLogEntry {
  FoldLogKind kind = FoldLogKind::Commit;
  double time = 0.0;          // the frame's time, seconds
  std::size_t fold = 0;       // which fold (from 1) was committed, undone or redone
  std::size_t foldCount = 0;  // folds in the fixed sheet afterwards
  ReflectionPlane plane;      // that fold's plane, sheet coordinates
  std::size_t trianglesBefore = 0;
  std::size_t trianglesAfter = 0;
  double maxEdgeLengthError = 0.0;    // of the fixed sheet afterwards: max |3D - 2D edge length|, m
  std::size_t selfIntersections = 0;  // triangle pairs of the fixed sheet afterwards that cross
  // In a symmetric design (engine/geometry/symmetry.hpp): the fold's images made with it (fold is
  // then the group's first), and for a commit those left out (their seed lay in a part this fold
  // moved) and those whose part overlapped an earlier fold's of the group.
  std::size_t images = 0;
  std::size_t skippedImages = 0;
  std::size_t overlappingImages = 0;
  // Folding toward a target (curvefold fit): the folded form's two-sided Hausdorff and Chamfer
  // distances to it afterwards (engine/fit/surface_distance.hpp), and its diagonal; 0: none.
  double hausdorff = 0.0, chamfer = 0.0, targetDiagonal = 0.0;
};

// The log entry as one JSON line (no newline): {"event":"commit","t":..,"fold":..,"folds":..,
// "plane":{"point":[..],"normal":[..]},"triangles_before":..,"triangles_after":..,
// "max_edge_length_error":..,"self_intersections":..}, and in a symmetric design
// "images":..,"skipped_images":.. (and "overlapping_images":.. when any); toward a target,
// "hausdorff", "chamfer" (m) and each relative to the target's diagonal.
std::string foldLogLine(const FoldLogEntry& entry);

// Largest |3D length - development length| over the sheet's edges: one pass over the triangles,
// cheaper than measure() and enough for the log.
double maxEdgeLengthError(const Sheet& sheet);

// Appends the commits, undos and redos among one frame's `events` to `log`, with the session as
// it is after that frame (foldsBefore and trianglesBefore: as it was before).
void appendFoldLog(std::vector<FoldLogEntry>& log, const FoldSession& session,
                   const std::vector<InteractionEvent>& events, double time,
                   std::size_t foldsBefore, std::size_t trianglesBefore);

// Steps through a recording frame by frame (a renderer's loop, or replayRecording). Holds a
// reference to the recording, which must outlive it.
class Player {
 public:
  // Builds the initial sheet; throws DesignError when the engine refuses the header's surface
  // (parseRecording has already checked it), RecordingError for a recording with frames the GPU
  // solver simulated (SimulationInput::solver), which cannot be replayed bit for bit.
  explicit Player(const Recording& recording, const InteractionThresholds& thresholds = {});
  Player(const Player&) = delete;
  Player& operator=(const Player&) = delete;

  bool done() const { return next_ >= recording_.frames.size(); }
  std::size_t nextFrame() const { return next_; }
  // Feeds the next frame to the core and logs the folds it committed, undid or redid.
  const InputFrame& step();

  const InteractionCore& core() const { return core_; }
  const FoldSession& session() const { return session_; }
  const std::vector<FoldLogEntry>& log() const { return log_; }
  // The header's surface with the folds now in the fixed sheet (a drag in progress is not one).
  Design design() const;

 private:
  const Recording& recording_;
  FoldSession session_;
  InteractionCore core_;
  std::vector<FoldLogEntry> log_;
  std::size_t next_ = 0;
};

struct ReplayProgress {
  std::size_t frame = 0;       // frames processed so far
  std::size_t frameCount = 0;  // frames in the recording
  double time = 0.0;           // recording time of the last frame, from the first frame
  double duration = 0.0;       // recording time of the last frame of all
};

struct ReplayOptions {
  // Sleep until each frame's time (demos); otherwise as fast as possible (tests, batch).
  bool realtime = false;
  InteractionThresholds thresholds;
  // Called after every frame (a progress bar throttles itself).
  std::function<void(const ReplayProgress&)> onFrame;
};

struct ReplayResult {
  Design design;  // the header's surface and the committed folds
  Sheet sheet;    // the final fixed sheet (what buildSheet(design) gives, bit for bit)
  std::vector<FoldLogEntry> log;
  std::size_t frameCount = 0;
  double duration = 0.0;            // seconds of recording
  bool endedWhileDragging = false;  // the recording stopped inside a drag, which was dropped
  // The simulated sheet's positions when the recording ends simulating (issue 39, 4), else empty.
  std::vector<glm::dvec3> simulated;
};

ReplayResult replayRecording(const Recording& recording, const ReplayOptions& options = {});

// The pace of a replay, for any replayer: calls step(frame) for each of the recording's frames in
// order (sleeping until its recorded time when options.realtime) and options.onFrame after each.
// Returns the recording's duration in seconds.
double replayFrames(const Recording& recording, const ReplayOptions& options,
                    const std::function<void(const InputFrame&)>& step);

}  // namespace curvefold
