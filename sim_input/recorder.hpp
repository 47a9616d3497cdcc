// Records a live session (docs/design.md 6): the header, then every input frame as it comes. A
// recording is a journal, written in place and never rewritten: lines are kept in memory and
// written, flushed and fsynced at each commit point, so a process killed at any moment leaves a
// file that replays every fold committed before it (at most the drag in progress is lost).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {

struct RecorderOptions {
  bool overwrite = false;  // replace an existing file instead of refusing it
};

class Recorder {
 public:
  // Creates the file and writes the header to disk. Throws FileError naming the path when the
  // file exists (unless options.overwrite) or cannot be written, RecordingError for a header the
  // reader would refuse.
  Recorder(const std::filesystem::path& path, const RecordingHeader& header,
           const RecorderOptions& options = {});
  // Writes what is pending; errors are swallowed here (call close() to see them).
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  // Keeps a frame in memory. Throws RecordingError, and keeps nothing, for a frame the reader
  // would refuse (a value that is not finite, a non-unit quaternion, time going backwards).
  void append(const InputFrame& frame);

  // Writes and fsyncs every pending frame. Call it after a frame that committed, undid or redid a
  // fold (see isCommitPoint), so a crash never loses committed work. Throws FileError; a write
  // that fails part way (a full disk) is cut back, so the file ends with a whole line.
  void commitPoint() { flush(); }
  void flush();
  // Flushes and closes the file; later appends throw. Throws FileError.
  void close();

  const std::filesystem::path& path() const { return path_; }
  std::size_t frameCount() const { return frameCount_; }
  std::size_t pendingFrames() const { return pendingFrames_; }

 private:
  void writeAll(const std::string& text);

  std::filesystem::path path_;
  int fd_ = -1;
  std::string pending_;
  std::size_t bytesWritten_ = 0;  // whole lines on disk
  std::size_t pendingFrames_ = 0;
  std::size_t frameCount_ = 0;
  double lastTime_;
};

// Whether a frame's interaction events changed the committed design (commit, undo or redo), so
// its recorder should make a commit point.
bool isCommitPoint(const std::vector<InteractionEvent>& events);

}  // namespace curvefold
