// The studio's target shape (issue 27, docs/design.md 9): a mesh the designer folds toward, shown
// as a ghost in the sheet's frame with its distance to the design, and the next folds toward it
// suggested on request. The target is read, checked and sampled on another thread (issue 38, 3),
// the search runs on a worker thread (SuggestionWorker) and the distances are measured off the
// frame too, so frames never wait for any of them: the frame only swaps in what is ready, and a
// load, a change of the design or of the document abandons the search in flight
// (SuggestionWorker::cancel, retarget) and leaves an old load or measure to finish unread.
// One measure throughout (issue 38, 4): the design's distance and what a suggestion would make it
// are both surfaceDistance with kDistanceSamples, so the suggestion's "before" is the distance
// line's figure and its "after" the figure the line shows once it is taken. A suggestion reaches
// the interaction core as input (InputFrame::suggestions), where it is recorded like the hands: a
// replay offers the same folds at the same moment without searching, so it makes the same design.
// The desktop window and the headset's panel share it.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/session/document.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/suggestion_worker.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/text/distance_text.hpp"

namespace curvefold::studio {

// The design to start from when the designer chose no sheet but brought a target (issue 38, 4):
// the catalogue surface sized to it as `fit` chooses one without --from (start_surface.hpp),
// after the same check of its units and place against the default square. Reads the target;
// throws a one-line error naming the file.
Design startForTarget(const std::string& path);

// The start `fit T` chooses without --from (issue 38, 4; fit_start.hpp's chooseFitStart): the
// rule's sheet revised by its first step toward a saddle or a vase, measured by a fitter with
// `fit`'s settings and seed, on `fit`'s default clock (60 s, of which the choice takes its share).
// The revisions cost seconds, so a window opens on startForTarget's sheet and takes this one from
// StudioTarget::reviseStart when it is ready. `cancelled` stops it (unset: never). Throws as
// startForTarget does, without the file's name.
Design fitStartForTarget(const TriangleMesh& target, const std::atomic<bool>* cancelled = nullptr);

// Whether two starts are the same sheet: the same generator and parameters, or the same mesh.
bool sameStart(const InitialSurface& a, const InitialSurface& b);

// What a studio (the desktop window, the headset) opens: the input named (a design file or a
// surface), else, with a target, the start chosen to match it (startForTarget), else
// defaultSurface; surfaceName is what the autosave and the exports are named after without an
// input.
struct StudioStart {
  Design design;
  std::string surfaceName;
};
StudioStart studioStart(const std::string& input, const std::string& target,
                        const std::string& defaultSurface);

class StudioTarget {
 public:
  // How many suggestions one request asks for (the panel's "Another" goes round them).
  static constexpr std::size_t kSuggestionsPerRequest = 3;
  // The samples the panel's distance is measured on (a tenth of a second at 10k triangles, off
  // the frame); `curvefold distance` takes more and is the one to quote.
  static constexpr std::size_t kDistanceSamples = 5'000;
  // With a search below the frame (searchNice > 0), the distance line's measures run this much
  // further below, so that a measure started with a search (a target loaded and Suggest asked at
  // once) takes the cores after it: the suggestion reaches the designer first (issue 38, 3).
  static constexpr int kMeasureBelowSearch = 5;

  // Reads a target file (readObjMesh; a test slows it down).
  using MeshReader = std::function<TriangleMesh(const std::string& path)>;

  // replaying: suggestions come from the frames (a replay's), and nothing is searched or measured;
  // a load is made at once (a replay runs as fast as it can, and the same way every time).
  // suggestionSeconds: how long a search may take before it answers with what it has.
  // searchNice: the nice its threads run at (a window's or headset's frames ask
  // SuggestionWorker::kYieldToFrames, so that the frame and a CPU renderer get the cores first);
  // the measures run kMeasureBelowSearch below it.
  explicit StudioTarget(bool replaying = false,
                        double suggestionSeconds = SuggestionWorker::kDefaultTimeLimit,
                        MeshReader reader = {}, int searchNice = 0);
  ~StudioTarget();
  StudioTarget(const StudioTarget&) = delete;
  StudioTarget& operator=(const StudioTarget&) = delete;

  // Starts reading the target (an OBJ in the sheet's frame), checking it against the document's
  // sheet and sampling it, on another thread; poll swaps it in when it is ready. The search in
  // flight is abandoned now. A failed load is one line in distanceLine (unreadable, no area, far
  // away or in other units), and the target before stays. A newer load replaces one under way.
  void load(const std::string& path, const session::Document& doc);
  // The same, on this thread, before any frame (the command line's --target): throws the line.
  void loadNow(const std::string& path, const session::Document& doc);
  bool loaded() const { return fitter_ != nullptr; }
  bool loading() const { return loading_.valid(); }
  // The target (sheet coordinates), for the ghost; null without one.
  const TriangleMesh* mesh() const;
  const std::string& path() const { return path_; }

  // Starts the search for the next folds of the document's committed design (a drag in
  // progress is not part of it); while a target loads, once it is there. Throws when there is no
  // target and none loading.
  void suggest(const session::Document& doc);
  // The worker (null without a target or while replaying), for tests and benchmarks.
  const SuggestionWorker* worker() const { return worker_.get(); }
  bool searching() const { return searching_; }

  // Once a frame, before the frame reaches the core and the recorder: a search that finished for
  // the design as it still is puts its folds into frame.suggestions (a replay's frame brings its
  // own). Also starts measuring the distance when the design changed.
  void poll(const session::Document& doc, InputFrame& frame);

  // Whether the next poll has something to take in (a load, an answer or a measure is ready):
  // a window that draws only when something changes looks here between frames. Cheap, never
  // waits.
  bool hasNews() const;

  // The part the suggestion the core offers moves, where it goes (sheet coordinates), for the
  // preview; null when unknown (a replay's suggestions come without their results).
  const TriangleMesh* offeredResult(const InteractionCore& core) const;

  // One line each for the panel: the distance ("no target", "loading ...", "measuring ...", a
  // failed load) and the suggestion ("searching ...", "suggestion 1 of 3: Chamfer 8.1 mm -> 5.2
  // mm", "no fold brings it closer", ...).
  std::string distanceLine() const;
  std::string suggestionLine(const InteractionCore& core) const;

  // The document was replaced (a new sheet, an opened design): what was found for the old one
  // goes; the target stays. A start still being revised is dropped.
  void documentReplaced();

  // After a window opened on startForTarget's sheet (the rule's choice alone, at once): chooses
  // the start `fit` would (fitStartForTarget) from the loaded target, on a thread of its own at
  // the search's nice, so no frame waits for its seconds. A no-op while replaying or without a
  // target.
  void reviseStart(const session::Document& doc);
  // Once a frame, before the frame's input reaches the core: the revised start, once, when it is
  // ready, is another sheet than the one open, and the designer has left the design as it opened
  // (no fold, no drag under way, no suggestion asked); the host opens it in place of the
  // document (and calls documentReplaced), and the suggestion line names it. Overtaken by a fold,
  // a Suggest, another target or document, it is dropped (its thread cancelled): the designer's
  // sheet is never swapped under their work. Never waits.
  // `busy`: the host's own work on the sheet open (a live simulation), which keeps it as a fold
  // does.
  std::optional<Design> takeRevisedStart(const session::Document& doc, bool busy = false);
  bool revisingStart() const { return revising_.valid(); }

 private:
  struct Measured {
    std::uint64_t revision = 0;
    const void* session = nullptr;
    SurfaceDistance distance;
  };
  // A target read, checked and sampled, or why not.
  struct Loaded {
    std::string path;
    std::shared_ptr<const FoldFitter> fitter;
    std::string error;
  };
  static Loaded read(const std::string& path, const Sheet& sheet, const MeshReader& reader);
  void swapIn(Loaded loaded, const session::Document& doc);
  void startSearch(const session::Document& doc);

  bool replaying_;
  double suggestionSeconds_;
  int searchNice_;
  MeshReader reader_;
  std::string path_;
  std::future<Loaded> loading_;
  std::string loadingPath_;
  std::string loadError_;          // the last load's failure, until the next load
  bool suggestAfterLoad_ = false;  // Suggest was asked while the target loaded
  // Superseded loads, left to finish unread (never waited for on a frame).
  std::vector<std::future<Loaded>> retiredLoads_;
  std::shared_ptr<const FoldFitter> fitter_;
  std::unique_ptr<SuggestionWorker> worker_;
  bool searching_ = false;
  std::uint64_t request_ = 0;
  // The design a search or the offers are for: its session and revision.
  const void* requestSession_ = nullptr;
  std::uint64_t requestRevision_ = 0;
  std::string answerNote_;              // why the last search offered nothing
  std::vector<FoldSuggestion> found_;   // the last answer, best first
  std::vector<TriangleMesh> moved_;     // each one's moved part, folded
  std::vector<SuggestedFold> offered_;  // what the last answer put into a frame
  // Each found suggestion measured as the design is (the panel's "after"), off the frame.
  std::future<std::vector<double>> measuringFound_;
  std::vector<double> foundChamfer_;
  std::optional<Measured> measured_;
  bool measuredCurrent_ = false;  // measured_ is of the design as it is
  std::future<Measured> measuring_;
  // Measures of a design or target no longer shown, left to finish (never waited for on a frame).
  std::vector<std::future<Measured>> retired_;
  std::vector<std::future<std::vector<double>>> retiredFound_;
  // Targets replaced by a newer one, let go on a thread of their own: freeing a target's trees and
  // samples is a large target's tens of milliseconds, which no frame should wait for.
  std::vector<std::future<void>> released_;
  void retireMeasuring();
  void retireFound();
  void reapRetired();

  // The start's revision (reviseStart): the design `fit` would start from, or why not.
  struct Revised {
    std::optional<Design> design;  // unset: the same sheet as the one open
    std::string kind;              // the revised sheet's generator
    std::string error;
  };
  std::future<Revised> revising_;
  std::shared_ptr<std::atomic<bool>> reviseCancel_;
  const void* reviseSession_ = nullptr;  // the document it is for, as it opened
  std::uint64_t reviseRevision_ = 0;
  std::string startNote_;  // what became of the revision, for the suggestion line
  std::vector<std::future<Revised>> retiredRevisions_;
  void dropRevision(const std::string& note);
};

}  // namespace curvefold::studio
