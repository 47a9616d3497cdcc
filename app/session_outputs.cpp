#include "app/session_outputs.hpp"

#include "engine/io/output_set.hpp"

#include <exception>
#include <filesystem>
#include <system_error>

#include "engine/io/atomic_file.hpp"
#include "sim_input/recorder.hpp"

namespace curvefold::cli {

SessionOutputs::SessionOutputs(std::string autosavePath, std::string recordPath,
                               std::function<Design()> designOf)
    : autosavePath_(std::move(autosavePath)),
      recordPath_(std::move(recordPath)),
      designOf_(std::move(designOf)) {
  if (!recordPath_.empty() && sameFile(recordPath_, autosavePath_))
    throw FileError("cannot record to " + recordPath_ +
                    ": it is the autosave too (each needs its own file)");
  std::error_code error;
  if (!recordPath_.empty() && std::filesystem::exists(recordPath_, error))
    throw FileError("cannot record to " + recordPath_ +
                    ": the file exists (choose another name or allow overwriting)");
}

SessionOutputs::~SessionOutputs() {
  finish();
}

void SessionOutputs::startRecording(const RecordingHeader& header) {
  if (recordPath_.empty() || recorder_ || finished_) return;
  recorder_ = std::make_unique<Recorder>(recordPath_, header);
}

void SessionOutputs::frame(const InputFrame& input, const std::vector<InteractionEvent>& events) {
  if (finished_) return;
  if (recorder_) {
    try {
      recorder_->append(input);
    } catch (const std::exception& e) {
      stopRecording(e.what());
    }
  }
  if (!isCommitPoint(events)) return;
  unsaved_ = true;
  save();  // the design first: it holds every committed fold whatever the recording does
  if (recorder_) {
    try {
      recorder_->commitPoint();
    } catch (const std::exception& e) {
      stopRecording(e.what());
    }
  }
}

bool SessionOutputs::save() noexcept {
  try {
    saveDesign(designOf_(), autosavePath_);
    unsaved_ = false;
    return true;
  } catch (const std::exception& e) {
    problems_.push_back(std::string("autosave failed (retried at the next fold): ") + e.what());
    return false;
  } catch (...) {
    problems_.push_back("autosave failed: unknown error");
    return false;
  }
}

void SessionOutputs::switchAutosave(std::string path) noexcept {
  if (finished_) return;
  if (unsaved_) save();
  unsaved_ = false;
  autosavePath_ = std::move(path);
}

void SessionOutputs::stopRecording(const std::string& why) noexcept {
  try {
    recorder_->close();
  } catch (...) {
    // The failure that stopped it is the one to report.
  }
  recorder_.reset();
  problems_.push_back("stopped recording to " + recordPath_ + ": " + why +
                      " (the file keeps every whole frame before it; the session goes on)");
}

bool SessionOutputs::finish(bool saveAlways) noexcept {
  if (finished_) return problems_.empty();
  finished_ = true;
  const bool saved = !(unsaved_ || saveAlways) || save();
  if (recorder_) {
    try {
      recorder_->close();
    } catch (const std::exception& e) {
      problems_.push_back(std::string("recording: ") + e.what());
    }
    recorder_.reset();
  }
  return saved;
}

std::vector<std::string> SessionOutputs::takeNewProblems() {
  std::vector<std::string> fresh(problems_.begin() + std::ptrdiff_t(problemsTaken_),
                                 problems_.end());
  problemsTaken_ = problems_.size();
  return fresh;
}

}  // namespace curvefold::cli
