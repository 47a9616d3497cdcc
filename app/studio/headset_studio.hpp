// The studio in the headset (issue 14): the studio panel (app/studio/studio_panel.hpp) on a card
// held by the non-dominant hand and worked by the dominant hand's aim ray, the trigger as its
// button and the thumbstick as its wheel; the panel button (Button::Panel) shows and hides it, and
// it is shown at start. Each input frame goes to the panel first, then to the interaction core,
// which then gets the buttons the panel pressed (undo, redo, ...) and is told whether the point
// hand is on the panel (so the tip does not grab through it).
//
// The studio runs the same with or without drawing: the headset draws its draw data into a
// texture, while a replay or a gesture script only runs it. Since the panel's actions come from
// the recorded hands like everything else, a studio recording replays to the same design.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/session/document.hpp"
#include "app/studio/studio_panel.hpp"
#include "app/studio/studio_target.hpp"
#include "interaction/live_simulation.hpp"
#include "interaction/panel_pointer.hpp"

struct ImGuiContext;
struct ImDrawData;

namespace curvefold::studio {

// What the studio asks of the program it runs in.
struct HeadsetStudioHost {
  // Renders the design to a PNG; null: PNG export says there is no renderer.
  std::function<void(const std::string& path)> exportPng;
  // The folded form as a picture for the PDF's cover; null: the PDF goes without it.
  std::function<std::optional<PdfPicture>()> foldedForm;
  // The document is about to be replaced (the old one is still there).
  std::function<void(const std::string& name)> documentReplacing;
  // The document was replaced (a new sheet, an opened design): drop what was made from the old.
  std::function<void()> documentReplaced;
  // See StudioActions: a replay sets one that writes nothing; null writes.
  std::function<void(const std::string& path, const std::function<void(const std::string&)>& write)>
      writeFile;
  std::function<void(const std::vector<std::string>& recent)> recentChanged;
  // See StudioActions: a panel action failed.
  std::function<void(const std::string& problem)> failed;
};

struct HeadsetStudioOptions {
  std::string exportDir = ".";  // exports go to <exportDir>/<design name>.<extension>
  std::string name;             // the design's name ("cone", a file's stem)
  std::vector<std::string> recent;
  Pose sheetFrame;  // where a new sheet starts
  glm::ivec2 pixels{480, 600};
  PanelPlacement placement = heldPanelPlacement();
  std::string target;      // a target shape (OBJ) to fold toward, loaded at the start
  bool replaying = false;  // a replay: suggestions come from the frames, nothing is searched
  // How long a suggestion may search before it answers with the best it has.
  double suggestionSeconds = SuggestionWorker::kDefaultTimeLimit;
  // The nice the search runs at (SuggestionWorker): the headset's frames ask kYieldToFrames.
  int searchNice = 0;
};

class HeadsetStudio {
 public:
  HeadsetStudio(session::Document& doc, HeadsetStudioOptions options, HeadsetStudioHost host = {});
  ~HeadsetStudio();
  HeadsetStudio(const HeadsetStudio&) = delete;
  HeadsetStudio& operator=(const HeadsetStudio&) = delete;

  // One input frame (its time never going back): the target (whose search may have finished: its
  // folds join the frame, for the recorder), the panel button, the ray, the panel (whose actions
  // act now), then the core.
  void process(InputFrame& frame, const StudioStats& stats = {});
  void process(const InputFrame& frame, const StudioStats& stats = {}) {
    InputFrame copy = frame;
    process(copy, stats);
  }

  bool shown() const { return shown_; }
  // Where the panel is (world), once its hand has been seen; it stays where it was while the hand
  // is lost.
  const std::optional<Pose>& worldFromPanel() const { return worldFromPanel_; }
  // This frame's ray on the panel's plane while the panel has the point hand (the ray is drawn
  // only then).
  std::optional<PanelRayHit> ray() const;
  PointTarget target() const { return pointer_.target(); }
  const PanelPlacement& placement() const { return options_.placement; }
  glm::ivec2 pixels() const { return options_.pixels; }
  bool creasePattern() const { return creasePattern_; }

  // The world position of the panel item with this label, when the panel shows it.
  std::optional<glm::dvec3> itemWorld(const std::string& label) const;
  // The panel's front (world), for a hand to point at it.
  std::optional<glm::dvec3> facing() const;

  // The last frame's draw data (none before the first frame or while hidden), and the context
  // it belongs to, for a renderer.
  ImDrawData* drawData() const;
  ImGuiContext* context() const { return context_; }
  const StudioPanel& panel() const { return panel_; }
  // The target shape the studio folds toward, and its suggestions.
  const StudioTarget& goal() const { return target_; }
  StudioPanel& panel() { return panel_; }

 private:
  void replace(const Design& design, const std::string& name);
  void nameDesign(const std::string& name);
  glm::dvec3 panelPoint(const glm::dvec2& pixel) const;

  session::Document& doc_;
  HeadsetStudioOptions options_;
  HeadsetStudioHost host_;
  ImGuiContext* context_ = nullptr;
  StudioPanel panel_;
  StudioTarget target_;
  PanelPointer pointer_;
  bool shown_ = true;
  bool creasePattern_ = true;
  std::uint32_t buttonsHeld_ = 0;
  std::optional<Pose> worldFromPanel_;
  std::optional<PanelRayHit> hit_;
  std::uint32_t pressedByPanel_ = 0;
  SimulationPuller puller_;  // the point hand's pull while simulating
  double lastTime_ = 0.0;
  bool drawn_ = false;
};

}  // namespace curvefold::studio
