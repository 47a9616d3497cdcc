// The desktop's own file chooser for the studio panel's Open and Save (issue 31): the XDG desktop
// portal's FileChooser when the session bus has one (GNOME, KDE and the others draw their own
// dialog, sandboxes included), else zenity when it is on PATH. The dialog is waited on by a worker
// thread, so frames go on while it is open. Without either the panel keeps its path fields only
// (the headset never has one).
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
  // null when there is neither.
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

// zenity's --file-selection, run as a child process in its own process group.
class ZenityPicker : public FilePicker {
 public:
  // zenity's full path when it is on PATH, or empty.
  static std::string find();
  explicit ZenityPicker(std::string program) : program_(std::move(program)) {}
  void start(bool save, const std::string& current) override;
  std::string name() const override { return "zenity"; }

 private:
  std::string program_;
};

// org.freedesktop.portal.FileChooser over D-Bus (GLib's GDBus), on a connection of the worker's
// own: OpenFile or SaveFile, then the Request's Response signal; a closing window closes the
// request, which ends the dialog.
class PortalPicker : public FilePicker {
 public:
  // The session bus's address when the portal is on it (running or activatable), or empty. Never
  // starts a bus: a session without DBUS_SESSION_BUS_ADDRESS or $XDG_RUNTIME_DIR/bus has none.
  static std::string find();
  explicit PortalPicker(std::string busAddress) : address_(std::move(busAddress)) {}
  void start(bool save, const std::string& current) override;
  std::string name() const override { return "the desktop portal"; }

 private:
  std::string address_;
};

}  // namespace curvefold::studio
