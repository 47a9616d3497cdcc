// The desktop's own file chooser for the studio panel's Open and Save (issue 31): zenity, when it
// is on PATH, run as a child process that a worker thread waits on, so frames go on while the
// dialog is open. Without it the panel keeps its path fields only (the headset never has one).
#pragma once

#include <sys/types.h>

#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace curvefold::studio {

class FilePicker {
 public:
  // The picker program found on PATH (zenity's full path), or empty when there is none.
  static std::string find();

  explicit FilePicker(std::string program);
  // Ends a dialog still open (the window is closing): never waits for a person.
  ~FilePicker();
  FilePicker(const FilePicker&) = delete;
  FilePicker& operator=(const FilePicker&) = delete;

  // Opens a dialog for a file to open, or (save) one to write, starting at `current`. Returns at
  // once; throws when the program cannot be started.
  void start(bool save, const std::string& current);
  // A dialog is open.
  bool busy() const { return worker_.joinable(); }

  struct Picked {
    std::string path;   // empty: the person cancelled
    std::string error;  // the program failed (one line)
  };
  // Once the dialog is done, what it gave; nothing while it is open or none was started. Never
  // waits.
  std::optional<Picked> poll();

 private:
  void wait(pid_t child, int output);

  std::string program_;
  std::thread worker_;
  int cancel_[2] = {-1, -1};  // written to end the dialog
  std::mutex mutex_;
  std::optional<Picked> done_;  // set by the worker, under mutex_
};

}  // namespace curvefold::studio
