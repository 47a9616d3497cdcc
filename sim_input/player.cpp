#include "sim_input/player.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/io/json_reader.hpp"

namespace curvefold {
namespace {

std::string_view kindName(FoldLogKind kind) {
  switch (kind) {
    case FoldLogKind::Commit:
      return "commit";
    case FoldLogKind::Undo:
      return "undo";
    case FoldLogKind::Redo:
      return "redo";
  }
  return "unknown";
}

}  // namespace

double maxEdgeLengthError(const Sheet& sheet) {
  double worst = 0.0;
  for (const Triangle& t : sheet.triangles) {
    for (int i = 0; i < 3; ++i) {
      const VertexIndex a = t[i], b = t[(i + 1) % 3];
      const double length3 = glm::distance(sheet.positions[a], sheet.positions[b]);
      const double length2 = glm::distance(sheet.development[a], sheet.development[b]);
      worst = std::max(worst, std::abs(length3 - length2));
    }
  }
  return worst;
}

std::string foldLogLine(const FoldLogEntry& entry) {
  using nlohmann::ordered_json;
  const ReflectionPlane& plane = entry.plane;
  ordered_json value;
  value["event"] = kindName(entry.kind);
  value["t"] = entry.time;
  value["fold"] = entry.fold;
  value["folds"] = entry.foldCount;
  value["plane"] = {
      {"point", ordered_json::array({plane.point.x, plane.point.y, plane.point.z})},
      {"normal", ordered_json::array({plane.normal.x, plane.normal.y, plane.normal.z})}};
  value["triangles_before"] = entry.trianglesBefore;
  value["triangles_after"] = entry.trianglesAfter;
  value["max_edge_length_error"] = entry.maxEdgeLengthError;
  value["self_intersections"] = entry.selfIntersections;
  // A symmetric design's group: the images that followed the fold, and what was left out.
  if (entry.images > 0 || entry.skippedImages > 0) {
    value["images"] = entry.images;
    value["skipped_images"] = entry.skippedImages;
  }
  if (entry.overlappingImages > 0) value["overlapping_images"] = entry.overlappingImages;
  if (entry.targetDiagonal > 0.0) {
    value["hausdorff"] = entry.hausdorff;
    value["chamfer"] = entry.chamfer;
    value["hausdorff_relative"] = entry.hausdorff / entry.targetDiagonal;
    value["chamfer_relative"] = entry.chamfer / entry.targetDiagonal;
  }
  return value.dump();
}

Player::Player(const Recording& recording, const InteractionThresholds& thresholds)
    : recording_(recording),
      session_(initialSheet(Design{recording.header.surface, {}}, "recording")),
      core_(session_, recording.header.sheetFrame, recording.header.handedness, thresholds) {
  if (!recording.header.symmetry.empty())
    session_.setSymmetry(parseSymmetry(recording.header.symmetry, session_.initial()));
  for (const InputFrame& frame : recording.frames)
    if (frame.simulation && frame.simulation->solver == LiveSolverKind::Gpu)
      throw RecordingError("the frame at t=" + shortestDouble(frame.time) +
                           " was simulated on the GPU solver, which is bit for bit only on the "
                           "device that ran it: a GPU run is not replayed (simulate on the CPU to "
                           "record a run that replays)");
}

const InputFrame& Player::step() {
  const InputFrame& frame = recording_.frames.at(next_++);
  const std::size_t foldsBefore = session_.foldCount();
  const std::size_t trianglesBefore = session_.fixed().triangleCount();
  core_.process(frame);
  appendFoldLog(log_, session_, core_.events(), frame.time, foldsBefore, trianglesBefore);
  return frame;
}

void appendFoldLog(std::vector<FoldLogEntry>& log, const FoldSession& session,
                   const std::vector<InteractionEvent>& events, double time,
                   std::size_t foldsBefore, std::size_t trianglesBefore) {
  std::vector<FoldLogKind> kinds;
  for (const InteractionEvent& event : events) {
    if (event.kind == InteractionEventKind::Commit) kinds.push_back(FoldLogKind::Commit);
    if (event.kind == InteractionEventKind::Undo) kinds.push_back(FoldLogKind::Undo);
    if (event.kind == InteractionEventKind::Redo) kinds.push_back(FoldLogKind::Redo);
  }
  // The core emits these only when the fixed sheet changed, one fold (or one symmetric fold's
  // group) each way. A frame with several (undo and redo pressed together) rebuilds the sheets in
  // between from the history, whose prefix none of them rewrites.
  const std::vector<FoldRecord>& history = session.folds();
  // The end of the group starting at fold `from` (0-based), and the start of the one ending at
  // `to`: a fold without a group is a group of its own.
  auto groupEnd = [&](std::size_t from) {
    std::size_t end = from + 1;
    while (history[from].group != 0 && end < history.size() &&
           history[end].group == history[from].group)
      ++end;
    return end;
  };
  auto groupStart = [&](std::size_t to) {
    std::size_t start = to - 1;
    while (history[to - 1].group != 0 && start > 0 &&
           history[start - 1].group == history[to - 1].group)
      --start;
    return start;
  };
  std::size_t count = foldsBefore;
  std::size_t triangles = trianglesBefore;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    FoldLogEntry entry;
    entry.kind = kinds[i];
    entry.time = time;
    const bool forward = kinds[i] != FoldLogKind::Undo;
    if (forward ? count >= history.size() : count == 0) continue;  // nothing the history shows
    const std::size_t first = forward ? count : groupStart(count);
    const std::size_t end = forward ? groupEnd(count) : count;
    entry.fold = first + 1;
    entry.images = end - first - 1;
    count = forward ? end : first;
    entry.foldCount = count;
    entry.plane = history[first].plane;
    if (kinds[i] == FoldLogKind::Commit && i + 1 == kinds.size()) {
      entry.skippedImages = session.lastSkippedImages();
      entry.overlappingImages = session.lastOverlappingImages();
    }
    entry.trianglesBefore = triangles;
    if (i + 1 == kinds.size()) {
      entry.trianglesAfter = session.fixed().triangleCount();
      entry.maxEdgeLengthError = maxEdgeLengthError(session.fixed());
      entry.selfIntersections = findSelfIntersections(session.fixed()).intersections.size();
    } else {
      const Sheet between =
          replayFolds(session.initial(),
                      std::vector<FoldRecord>(
                          history.begin(), history.begin() + static_cast<std::ptrdiff_t>(count)));
      entry.trianglesAfter = between.triangleCount();
      entry.maxEdgeLengthError = maxEdgeLengthError(between);
      entry.selfIntersections = findSelfIntersections(between).intersections.size();
    }
    triangles = entry.trianglesAfter;
    log.push_back(entry);
  }
}

Design Player::design() const {
  const std::vector<FoldRecord>& history = session_.folds();
  return Design{
      recording_.header.surface,
      std::vector<FoldRecord>(history.begin(),
                              history.begin() + static_cast<std::ptrdiff_t>(session_.foldCount())),
      recording_.header.symmetry};
}

double replayFrames(const Recording& recording, const ReplayOptions& options,
                    const std::function<void(const InputFrame&)>& step) {
  const std::vector<InputFrame>& frames = recording.frames;
  const double start = frames.empty() ? 0.0 : frames.front().time;
  ReplayProgress progress;
  progress.frameCount = frames.size();
  progress.duration = frames.empty() ? 0.0 : frames.back().time - start;
  const auto clockStart = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const double time = frames[i].time - start;
    if (options.realtime)
      std::this_thread::sleep_until(clockStart +
                                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                        std::chrono::duration<double>(time)));
    step(frames[i]);
    progress.frame = i + 1;
    progress.time = time;
    if (options.onFrame) options.onFrame(progress);
  }
  return progress.duration;
}

ReplayResult replayRecording(const Recording& recording, const ReplayOptions& options) {
  Player player(recording, options.thresholds);
  ReplayResult result;
  result.duration = replayFrames(recording, options, [&](const InputFrame&) { player.step(); });
  result.design = player.design();
  result.sheet = player.session().fixed();
  result.log = player.log();
  result.frameCount = recording.frames.size();
  result.endedWhileDragging = player.session().dragging();
  if (const LiveSimulation* simulation = player.core().simulation())
    result.simulated = simulation->sheet().positions;
  return result;
}

}  // namespace curvefold
