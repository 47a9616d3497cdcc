#include "app/session/session_outputs.hpp"

#include "engine/io/output_set.hpp"

#include <unistd.h>

#include <ctime>
#include <exception>
#include <filesystem>
#include <system_error>

#include "app/session/state_folder.hpp"
#include "engine/io/atomic_file.hpp"
#include "sim_input/recorder.hpp"

namespace curvefold::session {

SessionOutputs::SessionOutputs(std::string autosavePath, std::string recordPath,
                               std::function<Design()> designOf,
                               const std::vector<NamedInput>& inputs)
    : autosavePath_(std::move(autosavePath)),
      recordPath_(std::move(recordPath)),
      designOf_(std::move(designOf)) {
  refuseOutputsOverInputs({autosavePath_, recordPath_}, inputs);
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
  if (recordPath_.empty() || recorder_ || finished_ || stopped_) return;
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

bool SessionOutputs::save(bool last) noexcept {
  std::string why;
  try {
    saveDesign(designOf_(), autosavePath_);
    unsaved_ = false;
    return true;
  } catch (const std::exception& e) {
    why = e.what();
  } catch (...) {
    why = "unknown error";
  }
  if (last)
    rescue(why);
  else
    problems_.push_back("autosave failed (retried at the next fold): " + why);
  return false;
}

void SessionOutputs::rescue(const std::string& why) noexcept {
  std::string where;
  try {
    const std::filesystem::path folder = stateFolder();
    if (folder.empty()) throw FileError("no state folder (neither XDG_STATE_HOME nor HOME is set)");
    std::filesystem::create_directories(folder / "rescued");
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    std::string stem = std::filesystem::path(autosavePath_).filename().string();
    if (const auto dot = stem.find('.'); dot != std::string::npos && dot > 0) stem.resize(dot);
    const std::filesystem::path rescued =
        folder / "rescued" /
        (stem + "-" + stamp + "-" + std::to_string(::getpid()) + ".curvefold.json");
    saveDesign(designOf_(), rescued.string());
    where = "the design is saved to " + rescued.string() + " instead";
  } catch (const std::exception& e) {
    where = std::string("the design could not be saved anywhere: ") + e.what();
  } catch (...) {
    where = "the design could not be saved anywhere";
  }
  problems_.push_back("cannot write the autosave " + autosavePath_ + ": " + why + "; " + where);
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
  stopped_ = true;
  problems_.push_back("stopped recording to " + recordPath_ + ": " + why +
                      " (the file keeps every whole frame before it; the session goes on)");
}

bool SessionOutputs::finish(bool saveAlways) noexcept {
  if (finished_) return problems_.empty();
  finished_ = true;
  const bool saved = !(unsaved_ || saveAlways) || save(/*last=*/true);
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

}  // namespace curvefold::session
