// The studio panel (Dear ImGui): a new sheet from the catalog, save, open, export, undo, redo, the
// crease pattern, and live stats. One panel, two hosts: the desktop window draws it in its own
// ImGui frame, the headset will draw it onto a card held by the non-dominant hand (issue 14). The
// panel only builds widgets and says what was asked; the host does it (StudioActions), so each
// host keeps its own devices and files.
//
// Items are addressed by their label: the panel records where each one was last drawn
// (itemCentre), so a test or a gesture script can point at "Undo" rather than at coordinates.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/document.hpp"
#include "interaction/input_frame.hpp"

namespace curvefold::cli {

// What the host does when the panel asks. Each returns what to show ("wrote a.svg") or throws
// (the message is shown instead).
struct StudioActions {
  std::function<void(const Design& design, const std::string& name)> replaceDocument;
  std::function<void(Button button)> press;  // undo, redo, cancel, switch hands
  std::function<void(const std::string& path)> exportPng;
};

// What the panel shows that the host measures.
struct StudioStats {
  std::size_t drawnTriangles = 0;
  double dragUpdateMs = 0.0;
  double frameMs = 0.0;
};

class StudioPanel {
 public:
  // recording: the session is being recorded, so its sheet is fixed by the recording's header (no
  // new sheet, no open).
  // help: the host's controls, in a line or two.
  StudioPanel(bool recording, std::string help, std::string exportBase = "design");

  // Inside an ImGui frame: one window, "curvefold". creasePattern is the host's toggle.
  void draw(Document& doc, const StudioActions& actions, const StudioStats& stats,
            bool& creasePattern);

  const std::string& message() const { return message_; }
  void setMessage(std::string message) { message_ = std::move(message); }
  // Where the item with this label was drawn last frame (screen pixels), if it was.
  std::optional<glm::vec2> itemCentre(const std::string& label) const;

 private:
  void item(const char* label);  // records the last item's rectangle under its label
  void guarded(const std::string& done, const std::function<void()>& action);
  void resetParameters();

  bool recording_;
  std::string help_;
  int surfaceIndex_ = 0;
  std::vector<float> parameterValues_;
  char savePath_[512] = "design.curvefold.json";
  char openPath_[512] = "";
  char exportBase_[512] = "";
  std::string message_;
  double maxError_ = 0.0;
  const void* statsSession_ = nullptr;
  std::uint64_t statsRevision_ = ~std::uint64_t{0};
  std::map<std::string, glm::vec2> items_;
};

}  // namespace curvefold::cli
