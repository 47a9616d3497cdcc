// The desktop's own file chooser for the studio panel's Open and Save (issue 31): the XDG desktop
// portal's FileChooser when the session bus has one (GNOME, KDE and the others draw their own
// dialog, sandboxes included), else zenity when it is on PATH. The dialog is waited on by a worker
// thread, so frames go on while it is open. Without either the panel keeps its path fields only
// (the headset never has one). This is the base both pickers share (the worker, its cancel pipe,
// the result); each picker is its own pair: zenity_picker.hpp, portal_picker.hpp.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace curvefold::studio {

class FilePicker {
 public:
  // The desktop's picker: the portal when a session bus names one, else zenity found on PATH;
  // null when there is neither. Defined beside the portal (portal_picker.cpp, curvefold_panel):
  // only what links GDBus may choose it, so curvefold_studio stays free of GLib.
  static std::unique_ptr<FilePicker> find();

  // Ends a dialog still open (the window is closing): never waits for a person.
  virtual ~FilePicker();
  FilePicker(const FilePicker&) = delete;
  FilePicker& operator=(const FilePicker&) = delete;

  // Opens a dialog for a file to open, or (save) one to write, starting at `current`. Returns at
  // once; throws when the dialog cannot be started.
  virtual void start(bool save, const std::string& current) = 0;
  // A dialog is open.
  bool busy() const { return worker_.joinable(); }
  // Who draws the dialog, for messages: "the desktop portal" or "zenity".
  virtual std::string name() const = 0;

  struct Picked {
    std::string path;   // empty: the person cancelled
    std::string error;  // the dialog failed (one line)
  };
  // Once the dialog is done, what it gave; nothing while it is open or none was started. Never
  // waits.
  std::optional<Picked> poll();

 protected:
  FilePicker() = default;
  // Runs `dialog` on the worker. It is given a descriptor that becomes readable when the picker is
  // destroyed, and must then end its dialog and return soon.
  void launch(std::function<Picked(int cancelled)> dialog);

 private:
  std::thread worker_;
  int cancel_[2] = {-1, -1};  // written to end the dialog
  std::mutex mutex_;
  std::optional<Picked> done_;  // set by the worker, under mutex_
};

}  // namespace curvefold::studio
