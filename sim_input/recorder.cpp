#include "sim_input/recorder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <limits>

#include "engine/io/atomic_file.hpp"
#include "engine/io/json_reader.hpp"

namespace curvefold {
namespace {

std::string failure(const std::string& verb, const std::filesystem::path& path, int error) {
  return "cannot " + verb + " " + path.string() + ": " + std::strerror(error);
}

}  // namespace

Recorder::Recorder(const std::filesystem::path& path, const RecordingHeader& header,
                   const RecorderOptions& options)
    : path_(path), lastTime_(-std::numeric_limits<double>::infinity()) {
  // Checked before the file is created, so a bad header leaves nothing behind.
  const std::string line = headerLine(header) + "\n";
  // O_EXCL refuses an existing file (another session's journal) without a check-then-open race.
  const int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (options.overwrite ? O_TRUNC : O_EXCL);
  fd_ = ::open(path.c_str(), flags, 0666);
  if (fd_ < 0) {
    if (errno == EEXIST)
      throw FileError("cannot record to " + path.string() +
                      ": the file exists (choose another name or allow overwriting)");
    throw FileError(failure("write", path, errno));
  }
  pending_ = line;
  try {
    flush();
  } catch (...) {
    // A file without its whole header is no recording.
    ::close(fd_);
    fd_ = -1;
    ::unlink(path.c_str());
    throw;
  }
}

Recorder::~Recorder() {
  try {
    close();
  } catch (...) {
    // A destructor cannot report; close() is the call that does.
  }
}

void Recorder::append(const InputFrame& frame) {
  if (fd_ < 0) throw FileError("cannot write " + path_.string() + ": the recording is closed");
  if (frame.time < lastTime_)
    throw RecordingError("cannot record frame at t=" + shortestDouble(frame.time) +
                         ": time goes backwards (after t=" + shortestDouble(lastTime_) + ")");
  std::string line = frameLine(frame);
  pending_ += line;
  pending_ += '\n';
  lastTime_ = frame.time;
  ++pendingFrames_;
  ++frameCount_;
}

void Recorder::writeAll(const std::string& text) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t written = ::write(fd_, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      throw FileError(failure("write", path_, errno));
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

void Recorder::flush() {
  if (fd_ < 0) return;
  if (!pending_.empty()) {
    try {
      writeAll(pending_);
    } catch (const FileError&) {
      // A full disk may take half of the pending lines: cut the file back to its last whole line,
      // so that it stays a recording that replays every frame it holds.
      if (::ftruncate(fd_, static_cast<off_t>(bytesWritten_)) == 0)
        ::lseek(fd_, static_cast<off_t>(bytesWritten_), SEEK_SET);
      throw;
    }
    bytesWritten_ += pending_.size();
    pending_.clear();
    pendingFrames_ = 0;
  }
  if (::fsync(fd_) != 0 && errno != EINVAL) throw FileError(failure("write", path_, errno));
}

void Recorder::close() {
  if (fd_ < 0) return;
  // The descriptor is closed even when the last write fails, so close() is called once.
  struct Closer {
    int& fd;
    ~Closer() {
      ::close(fd);
      fd = -1;
    }
  } closer{fd_};
  flush();
}

bool isCommitPoint(const std::vector<InteractionEvent>& events) {
  for (const InteractionEvent& event : events)
    if (event.kind == InteractionEventKind::Commit || event.kind == InteractionEventKind::Undo ||
        event.kind == InteractionEventKind::Redo)
      return true;
  return false;
}

}  // namespace curvefold
