// The studio panel (Dear ImGui): a new sheet from the catalog (with a symmetry), save, open,
// export, undo, redo, the crease pattern, and live stats. One panel, two hosts: the desktop window
// draws it in its own ImGui frame, the headset will draw it onto a card held by the non-dominant
// hand (issue 14). The panel only builds widgets and says what was asked; the host does it
// (StudioActions), so each host keeps its own devices and files.
//
// Items are addressed by their label: the panel records where each one was last drawn
// (itemCentre), so a test or a gesture script can point at "Undo" rather than at coordinates.
#pragma once

#include <functional>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/session/document.hpp"
#include "app/studio/file_picker.hpp"
#include "engine/fabrication/crease_pattern_pdf.hpp"
#include "interaction/input_frame.hpp"

namespace curvefold::studio {

// What the host does when the panel asks. Each returns what to show ("wrote a.svg") or throws
// (the message is shown instead).
struct StudioActions {
  std::function<void(const Design& design, const std::string& name)> replaceDocument;
  std::function<void(Button button)> press;  // undo, redo, cancel, switch hands
  std::function<void(const std::string& path)> exportPng;
  // Optional: puts the sheet back where it started, at scale 1 (the headset's two-hand scale).
  std::function<void()> resetView;
  // Optional: writes a file the panel asked for by calling `write(path)`; a replay, which must
  // not touch the disk, leaves it out and the panel writes nothing, saying what it would have.
  // Without it (null), the panel writes.
  std::function<void(const std::string& path, const std::function<void(const std::string&)>& write)>
      writeFile;
  // Optional: the folded form as a picture, for the cover of the PDF (without it, none there).
  std::function<std::optional<PdfPicture>()> foldedForm;
  // Optional: a target shape to fold toward (issue 27): load it, and ask for the next fold. With
  // them the panel has its "Target" section.
  std::function<void(const std::string& path)> loadTarget;
  std::function<void()> suggest;
  // Optional: the recent designs changed (a design was saved or opened): the host keeps the list.
  std::function<void(const std::vector<std::string>& recent)> recentChanged;
  // Optional: an action failed (an export onto a full or read-only disk). The panel shows it;
  // the host also says it where it outlives the panel (stderr, its summary).
  std::function<void(const std::string& problem)> failed;
};

// What the panel shows that the host measures.
struct StudioStats {
  std::size_t drawnTriangles = 0;
  double dragUpdateMs = 0.0;
  double frameMs = 0.0;
  // The target section's two lines (StudioTarget::distanceLine and suggestionLine).
  std::string targetLine, suggestionLine;
};

// `text` broken at its spaces so that each line fits `width` in the current ImGui font (ImGui's
// own wrap also breaks after a '.', which split "Chamfer 0.474 mm" as "0." / "474"); a word wider
// than `width` is left whole on a line of its own, for ImGui to wrap.
std::string wrapAtSpaces(const std::string& text, float width);

// `path` as a field `width` wide shows it when it is longer: its end (the file's name) after
// "...", cut at a character; `path` itself when it fits.
std::string pathEnd(const std::string& path, float width);

class StudioPanel {
 public:
  // recording: the session is being recorded, so its sheet is fixed by the recording's header (no
  // new sheet, no open).
  // help: the host's controls, in a line or two.
  StudioPanel(bool recording, std::string help, std::string exportBase = "design");

  // Inside an ImGui frame: one window, "curvefold". creasePattern is the host's toggle.
  void draw(session::Document& doc, const StudioActions& actions, const StudioStats& stats,
            bool& creasePattern);

  // Where exports go (a path without its extension) and where Save writes.
  void setExportBase(const std::string& base);
  void setSavePath(const std::string& path);
  const std::string& exportBase() const { return exportBase_; }
  const std::string& savePath() const { return savePath_; }
  const std::string& openPath() const { return openPath_; }
  // Names Save's file and the exports after the design `name` (a surface, or the file it was
  // opened from): <name>.curvefold.json and <name>.<extension>, in the files folder when one is
  // set, else beside the opened file. The panel does it itself for the designs it opens or makes.
  void nameDesign(const std::string& name);
  void setFilesDir(const std::string& dir) { filesDir_ = dir; }
  // The desktop's own items, each beside an item both hosts have, so nothing else moves: the
  // recent designs beside Open and, with the desktop portal or zenity, "Browse..." beside Open and
  // Save. Off in the headset (no desktop there, and its recorded pointing must find the items it
  // found). `findPicker` is the desktop's picker finder; the default, FilePicker::find, lives in
  // curvefold_panel (GDBus) and is named by the caller, so this library (curvefold_studio, which
  // the Python module's replay links) needs no GLib.
  void setDesktop(bool desktop, const std::function<std::unique_ptr<FilePicker>()>& findPicker =
                                    FilePicker::find);
  // The target path field's text.
  void setTargetPath(const std::string& path);
  // The recent designs, newest first (at most kMaxRecentDesigns).
  void setRecent(std::vector<std::string> recent);
  const std::vector<std::string>& recent() const { return recent_; }
  // The window fills the ImGui display (a headset's panel texture) instead of floating.
  void setFillsDisplay(bool fills) { fillsDisplay_ = fills; }

  // The live simulation (issue 39, 4; the panel's "Simulate" section): the fold amount the slider
  // asks for while "simulate" is on (0..100), else none; the host puts it into the frame
  // (liveSimulationInput) for the core. Strain colours: asked for (the renderer's per-vertex colour
  // shows LiveSimulation::vertexStrain once it has one; until then the panel prints the largest).
  std::optional<double> simulationPercent() const;
  bool strainColours() const { return simulating_ && strainColours_; }
  // Sets the section's state (a test, or a host restoring it).
  void setSimulation(bool on, double percent);
  // The solver the host puts into the frame (SimulationInput::solver): the "GPU" checkbox, shown
  // only where the host has a device that can (setGpuSolverAvailable; `design --gpu` ticks it).
  LiveSolverKind simulationSolver() const {
    return gpuAvailable_ && gpuSolver_ ? LiveSolverKind::Gpu : LiveSolverKind::Cpu;
  }
  void setGpuSolverAvailable(bool available) { gpuAvailable_ = available; }
  void setGpuSolver(bool on) { gpuSolver_ = on; }

  const std::string& message() const { return message_; }
  void setMessage(std::string message) { message_ = std::move(message); }
  // Where the item with this label was drawn last frame (screen pixels), if it was.
  std::optional<glm::vec2> itemCentre(const std::string& label) const;

 private:
  // Rows of text the target section's two lines have, wrapped, at the narrowest panel.
  static constexpr int kTargetLineRows = 5;
  void item(const char* label);  // records the last item's rectangle under its label
  void targetLines(const StudioStats& stats);
  void guarded(const StudioActions& actions, const std::string& done,
               const std::function<void()>& action);
  void resetParameters();
  // The catalog surface with the sliders' parameters.
  GeneratedSurface chosenSurface() const;
  // Finds the symmetries of chosenSurface() in the background once per surface and parameters,
  // one search at a time, and takes a finished search's list.
  void findSymmetries();
  // Lists the symmetries of chosenSurface() when the list opens: the background's, waited for
  // when not done yet.
  void refreshSymmetries();
  void remember(const std::string& designPath, const StudioActions& actions);
  // A finished dialog's path goes into the field it was opened for.
  void takePicked();
  void browse(bool save);
  // The steps of draw(), top to bottom.
  bool button(const char* label);  // a button whose rectangle item() records
  void beginWindow();
  void drawNewSheet(const StudioActions& actions);
  // Over a path field that is not being edited, its end (pathEnd): ImGui draws a field's text
  // from its start, which hid a long path's file name.
  void showPathEnd(const std::string& path, float fieldWidth);
  void drawSymmetryChoice();
  void drawEditButtons(const StudioActions& actions, bool& creasePattern);
  void browseButton(const char* label, bool save);
  // Save and Open; returns how to open a design (null while recording, which opens none).
  std::function<void(const std::string&)> drawSaveAndOpen(session::Document& doc,
                                                          const StudioActions& actions);
  std::optional<std::string> drawRecentBesideOpen();  // the desktop's combo; the one chosen
  void drawExports(session::Document& doc, const StudioActions& actions);
  void drawTarget(session::Document& doc, const StudioActions& actions, const StudioStats& stats);
  void drawRecentDesigns(const std::function<void(const std::string&)>& open);
  void drawFacts(const session::Document& doc, const StudioStats& stats);
  // The "Simulate" section: its own items, after every item a recorded session points at.
  void drawSimulation(const session::Document& doc);
  void writeThrough(const StudioActions& actions, const std::string& path,
                    const std::function<void(const std::string&)>& write);

  bool recording_;
  std::string help_;
  int surfaceIndex_ = 0;
  std::vector<float> parameterValues_;
  static constexpr const char* kNoSymmetry = "none";
  std::string symmetry_ = kNoSymmetry;  // of the new sheet
  std::vector<std::string> symmetryChoices_;
  std::optional<GeneratedSurface> symmetriesFor_;  // the surface symmetryChoices_ are of
  std::future<std::vector<std::string>> finding_;  // the search under way, for findingFor_
  std::optional<GeneratedSurface> findingFor_;
  // Strings, not fixed buffers: a long path is kept whole, never cut.
  std::string savePath_ = "design.curvefold.json";
  std::string openPath_;
  std::string exportBase_;
  std::string targetPath_;
  std::string message_;
  double maxError_ = 0.0;
  const void* statsSession_ = nullptr;
  std::uint64_t statsRevision_ = ~std::uint64_t{0};
  std::map<std::string, glm::vec2> items_;
  std::vector<std::string> recent_;
  bool fillsDisplay_ = false;
  std::optional<std::string> filesDir_;
  bool desktop_ = false;
  std::unique_ptr<FilePicker> picker_;  // null without the portal or zenity
  bool pickingSave_ = false;            // the dialog open is Save's, else Open's
  bool simulating_ = false;
  float foldPercent_ = 100.0f;  // a new simulation folds from flat to the design
  bool strainColours_ = false;
  bool gpuAvailable_ = false, gpuSolver_ = false;
};

}  // namespace curvefold::studio
