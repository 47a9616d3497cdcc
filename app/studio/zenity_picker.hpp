// zenity's file chooser for the studio panel (issue 31): `zenity --file-selection`, the desktop's
// picker when no XDG portal answers (FilePicker::find). Its child runs in its own process group,
// ended when the picker is destroyed.
#pragma once

#include <string>
#include <utility>

#include "app/studio/file_picker.hpp"

namespace curvefold::studio {

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

}  // namespace curvefold::studio
