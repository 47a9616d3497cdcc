// The XDG desktop portal's file chooser for the studio panel (issue 31), over GLib's GDBus (in
// curvefold_panel, so the studio library below stays free of GLib).
#pragma once

#include <string>
#include <utility>

#include "app/studio/file_picker.hpp"

namespace curvefold::studio {

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
