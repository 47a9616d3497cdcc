// The files a live session keeps (the desktop designer, `curvefold xr`): the autosave, rewritten
// after every committed fold, and the optional recording (a journal; sim_input/recorder.hpp).
//
// Neither is created before the session can start (a window, an OpenXR session): a session that
// never starts leaves no file behind, and its retry is not refused. One output failing stops
// neither the other nor the session: at a commit point the design is saved first, then the
// recording's frames are made durable; a recording that cannot be written stops for the rest of
// the session (its file keeps only whole lines) and says so, while folding goes on and the
// autosave keeps every fold. Every way out of a session (its end, an exception, a lost runtime)
// goes through finish(), which the destructor calls when nothing else did; when the autosave
// cannot be written then, the design is rescued into the state folder and the message says where.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/io/design_document.hpp"
#include "engine/io/output_set.hpp"
#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {
class Recorder;
}

namespace curvefold::session {

class SessionOutputs {
 public:
  // designOf gives the design as it is (the folds committed so far). An existing recordPath, or
  // either path naming one of `inputs` (the target, the recording watched), is refused now
  // (FileError), before any window or session is made; nothing is created yet.
  SessionOutputs(std::string autosavePath, std::string recordPath, std::function<Design()> designOf,
                 const std::vector<NamedInput>& inputs = {});
  ~SessionOutputs();
  SessionOutputs(const SessionOutputs&) = delete;
  SessionOutputs& operator=(const SessionOutputs&) = delete;

  bool wantsRecording() const { return !recordPath_.empty(); }
  bool recording() const { return recorder_ != nullptr; }
  const std::string& autosavePath() const { return autosavePath_; }
  const std::string& recordPath() const { return recordPath_; }

  // Creates the recording with its header, once the session has started (a no-op without
  // --record, when it has already started, or once it stopped). Throws FileError or
  // RecordingError.
  void startRecording(const RecordingHeader& header);

  // After each processed input frame: records it, and at a commit point (a commit, undo or redo
  // among events) saves the design, then makes the recording durable. Never throws: a failure is
  // kept in problems() (and a failing recording stops).
  void frame(const InputFrame& input, const std::vector<InteractionEvent>& events);

  // The session moves to another design (a new sheet, an opened file): the one it leaves stays in
  // its autosave (saved now if its last save failed), and the next is autosaved at `path`.
  // Call it before the design changes. Never throws.
  void switchAutosave(std::string path) noexcept;

  // Saves the design (when a commit point happened since the last good save, or always when
  // saveAlways) and closes the recording. Runs once; never throws. Returns false when the design
  // could not be saved at its autosave; the last of problems() says why and where it was rescued
  // to (stateFolder()/rescued/NAME-TIME.curvefold.json), or that it could not be.
  bool finish(bool saveAlways = false) noexcept;

  // What went wrong so far, one line each, oldest first (for the panel and the final report).
  const std::vector<std::string>& problems() const { return problems_; }
  // Problems not yet taken, for a panel that shows each once.
  std::vector<std::string> takeNewProblems();

 private:
  bool save(bool last = false) noexcept;
  void rescue(const std::string& why) noexcept;
  void stopRecording(const std::string& why) noexcept;

  std::string autosavePath_, recordPath_;
  std::function<Design()> designOf_;
  std::unique_ptr<Recorder> recorder_;
  bool unsaved_ = false;  // a commit point whose design is not on disk yet
  bool stopped_ = false;  // the recording failed: it is not started again
  bool finished_ = false;
  std::vector<std::string> problems_;
  std::size_t problemsTaken_ = 0;
};

}  // namespace curvefold::session
