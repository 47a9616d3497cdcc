#include "app/studio/studio_target.hpp"

#include <pthread.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <variant>

#include "engine/fit/fit_start.hpp"
#include "engine/fit/start_surface.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold::studio {

namespace {

// The triangles of `folded` (a fold of `before`, whose vertices it keeps by index and appends to)
// that the fold moved: those with a kept vertex that moved. The rest lie where the sheet is, and
// a preview drawn over them would only veil it.
TriangleMesh movedPart(const Sheet& before, const Sheet& folded) {
  TriangleMesh part;
  part.positions = folded.positions;
  const std::size_t kept = std::min(before.vertexCount(), folded.vertexCount());
  for (const Triangle& t : folded.triangles) {
    bool moved = false;
    for (const VertexIndex v : t)
      moved = moved || (v < kept && folded.positions[v] != before.positions[v]);
    if (moved)
      part.triangles.push_back({std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
  }
  return part;
}

// A measure's own thread (std::async starts one per task) below the search's nice: beside a frame
// loop it takes the cores after the frame and the renderer, and after the search, so it neither
// runs ahead of an abandoned search that has to reach its next check (a measure of 10k triangles
// at nice 0 took the core from the niced search for 100-200 ms of CPU after each design change)
// nor slows a new one (about a tenth of its CPU, measured beside it after a load).
void measureAtNice(int searchNice) {
  if (searchNice <= 0) return;
  const int nice = std::min(19, searchNice + StudioTarget::kMeasureBelowSearch);
  const auto thread = id_t(syscall(SYS_gettid));
  errno = 0;
  const int now = getpriority(PRIO_PROCESS, thread);
  if (errno == 0 && now < nice) setpriority(PRIO_PROCESS, thread, nice);
}

// The design a chosen start opens as. A sheet moved onto the target (a swept parabola on a
// saddle) is embedded as it lies, as `fit` embeds it: its parameters ("curvature") are the
// placement's, not the catalogue surface's, which refused them and the window did not open.
Design designOf(const StartChoice& start) {
  if (start.placed) return Design{*start.placed, {}};
  return Design{GeneratedSurface{start.surface, start.parameters}, {}};
}

// `fit`'s --time when none is given (fit_commands.cpp), of which the start's choice takes its
// share (kStartShare): the studio's revision is cut where `fit T` would cut it.
constexpr double kFitDefaultSeconds = 60.0;

}  // namespace

Design startForTarget(const std::string& path) {
  const TriangleMesh target = readObjMesh(path);
  try {
    checkTarget(target);
    // Units and place as a sheet at the catalogue's defaults has them: a target in millimetres
    // is refused, not met by a sheet a thousand times too large.
    checkTargetAgainst(target, makeSurface("square"));
    return designOf(chooseStart(target));
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

Design fitStartForTarget(const TriangleMesh& target, const std::atomic<bool>* cancelled) {
  // `fit`'s fitter (its default settings and seed 1, as makeFitter makes it without options).
  const FoldFitter fitter(target);
  FitStartClock clock;
  clock.seconds = kFitDefaultSeconds;
  clock.cancelled = cancelled;
  return designOf(chooseFitStart(fitter, "", std::nullopt, clock).choice);
}

bool sameStart(const InitialSurface& a, const InitialSurface& b) {
  const auto* generatedA = std::get_if<GeneratedSurface>(&a);
  const auto* generatedB = std::get_if<GeneratedSurface>(&b);
  if (generatedA || generatedB) return generatedA && generatedB && *generatedA == *generatedB;
  const Sheet& sheetA = std::get<Sheet>(a);
  const Sheet& sheetB = std::get<Sheet>(b);
  return sheetA.positions == sheetB.positions && sheetA.triangles == sheetB.triangles;
}

StudioStart studioStart(const std::string& input, const std::string& target,
                        const std::string& defaultSurface) {
  if (input.empty() && !target.empty()) {
    Design design = startForTarget(target);
    const auto* generated = std::get_if<GeneratedSurface>(&design.surface);
    const std::string name = generated ? generated->generator : "start";
    return {std::move(design), name};
  }
  return {session::designFor(input, defaultSurface), defaultSurface};
}

StudioTarget::StudioTarget(bool replaying, double suggestionSeconds, MeshReader reader,
                           int searchNice)
    : replaying_(replaying),
      suggestionSeconds_(suggestionSeconds),
      searchNice_(searchNice),
      reader_(reader ? std::move(reader) : MeshReader(readObjMesh)) {}

// The worker, the loads and the measures still running are waited for here, when the studio ends
// (each stops at its next check, or within a measure or a read).
StudioTarget::~StudioTarget() {
  if (reviseCancel_) *reviseCancel_ = true;  // the start's revision stops at its next check
}

void StudioTarget::retireMeasuring() {
  // A future of std::async waits for its task when destroyed: kept until it is ready.
  if (measuring_.valid()) retired_.push_back(std::move(measuring_));
  measuring_ = {};
}

void StudioTarget::retireFound() {
  if (measuringFound_.valid()) retiredFound_.push_back(std::move(measuringFound_));
  measuringFound_ = {};
  foundChamfer_.clear();
}

namespace {

template <typename T>
bool isReady(const std::future<T>& f) {
  return f.valid() && f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

template <typename T>
void reap(std::vector<std::future<T>>& futures) {
  std::erase_if(futures, [](const std::future<T>& f) { return isReady(f); });
}

}  // namespace

void StudioTarget::reapRetired() {
  reap(retired_);
  reap(retiredFound_);
  reap(retiredLoads_);
  reap(released_);
  reap(retiredRevisions_);
}

StudioTarget::Loaded StudioTarget::read(const std::string& path, const Sheet& sheet,
                                        const MeshReader& reader) {
  Loaded loaded;
  loaded.path = path;
  try {
    // An offer is one drag (a hand can make it, a recording keeps it): no rings of folds.
    FitSettings settings;
    settings.rings = 0;
    auto fitter = std::make_shared<const FoldFitter>(reader(path), settings);
    fitter->checkAgainst(sheet);
    loaded.fitter = std::move(fitter);
  } catch (const InvalidTarget& e) {
    loaded.error = path + ": " + e.what();
  } catch (const std::exception& e) {
    loaded.error = e.what();  // the reader's errors name the file
  }
  return loaded;
}

void StudioTarget::load(const std::string& path, const session::Document& doc) {
  // The user asked for another target: what is searched toward the old one is of no use.
  if (worker_) worker_->cancel();
  if (revising_.valid()) dropRevision("");
  searching_ = false;
  suggestAfterLoad_ = false;
  answerNote_.clear();
  loadError_.clear();
  if (loading_.valid()) retiredLoads_.push_back(std::move(loading_));
  loading_ = {};
  if (replaying_) {
    swapIn(read(path, doc.session->initial(), reader_), doc);
    return;
  }
  loadingPath_ = path;
  loading_ = std::async(
      std::launch::async,
      [path, reader = reader_, sheet = std::make_shared<const Sheet>(doc.session->initial())] {
        return read(path, *sheet, reader);
      });
}

void StudioTarget::loadNow(const std::string& path, const session::Document& doc) {
  Loaded loaded = read(path, doc.session->initial(), reader_);
  if (!loaded.error.empty()) throw std::runtime_error(loaded.error);
  if (loading_.valid()) retiredLoads_.push_back(std::move(loading_));
  loading_ = {};
  swapIn(std::move(loaded), doc);
}

void StudioTarget::swapIn(Loaded loaded, const session::Document& doc) {
  if (!loaded.error.empty()) {
    loadError_ = std::move(loaded.error);
    searching_ = false;
    suggestAfterLoad_ = false;
    return;
  }
  // The old target's search (if any) is abandoned and its measures left to finish off the frame.
  retireMeasuring();
  retireFound();
  std::shared_ptr<const FoldFitter> old = std::move(fitter_);
  fitter_ = std::move(loaded.fitter);
  path_ = std::move(loaded.path);
  loadError_.clear();
  if (!replaying_) {
    if (worker_)
      worker_->retarget(fitter_);
    else
      worker_ = std::make_unique<SuggestionWorker>(fitter_, suggestionSeconds_, searchNice_);
  }
  // The worker holds the new target now: the old one goes off the frame (the last holder frees it,
  // here or in a measure or search still finishing).
  if (old && !replaying_)
    released_.push_back(
        std::async(std::launch::async, [old = std::move(old)]() mutable { old.reset(); }));
  measured_.reset();
  measuredCurrent_ = false;
  answerNote_.clear();
  found_.clear();
  moved_.clear();
  offered_.clear();
  const bool sameDesign =
      requestSession_ == doc.session.get() && requestRevision_ == doc.session->designRevision();
  if (suggestAfterLoad_ && sameDesign && !replaying_) {
    startSearch(doc);
  } else {
    searching_ = false;
  }
  suggestAfterLoad_ = false;
}

const TriangleMesh* StudioTarget::mesh() const {
  return fitter_ ? &fitter_->target() : nullptr;
}

void StudioTarget::suggest(const session::Document& doc) {
  if (!fitter_ && !loading_.valid())
    throw std::runtime_error("no target to suggest toward: load one first");
  requestSession_ = doc.session.get();
  requestRevision_ = doc.session->designRevision();
  searching_ = true;
  answerNote_.clear();
  if (replaying_) return;  // the recording brings what was found
  if (loading_.valid()) {
    if (worker_) worker_->cancel();  // toward the target that is on its way, not the old one
    suggestAfterLoad_ = true;
    return;
  }
  startSearch(doc);
}

void StudioTarget::startSearch(const session::Document& doc) {
  searching_ = true;
  const FoldSession& session = *doc.session;
  DesignSnapshot snapshot;
  snapshot.initial = std::make_shared<const Sheet>(session.initial());
  snapshot.folds.assign(session.folds().begin(), session.folds().begin() + session.foldCount());
  snapshot.symmetry = session.symmetry() ? session.symmetry()->name() : "";
  request_ = worker_->request(std::move(snapshot), kSuggestionsPerRequest);
}

void StudioTarget::poll(const session::Document& doc, InputFrame& frame) {
  const bool sameDesign =
      requestSession_ == doc.session.get() && requestRevision_ == doc.session->designRevision();
  reapRetired();
  if (isReady(loading_)) {
    Loaded loaded = loading_.get();
    loading_ = {};
    swapIn(std::move(loaded), doc);
  }
  if (searching_ && !sameDesign) {
    // Folded, undone or replaced while searching: what comes is for another design.
    if (worker_) worker_->cancel();
    searching_ = false;
    suggestAfterLoad_ = false;
    answerNote_ = "the design changed while searching: suggest again";
  }
  if (replaying_) {
    if (!frame.suggestions.empty()) {
      searching_ = false;
      found_.clear();
      moved_.clear();
      offered_ = frame.suggestions;
    }
  } else if (worker_) {
    std::optional<SuggestionWorker::Answer> answer = worker_->take();
    if (answer && searching_ && answer->request == request_) {
      searching_ = false;
      if (!answer->error.empty())
        answerNote_ = answer->error;
      else if (answer->suggestions.empty())
        answerNote_ = "no fold found brings it closer";
      found_ = std::move(answer->suggestions);
      offered_.clear();
      moved_.clear();
      for (const FoldSuggestion& suggestion : found_)
        moved_.push_back(movedPart(doc.session->fixed(), suggestion.sheet));
      // What each would make the design, in the distance line's measure, off the frame.
      retireFound();
      std::vector<TriangleMesh> results;
      for (const FoldSuggestion& suggestion : found_) results.push_back(meshOf(suggestion.sheet));
      measuringFound_ = std::async(
          std::launch::async, [fitter = fitter_, results = std::move(results), nice = searchNice_] {
            measureAtNice(nice);
            std::vector<double> chamfer;
            for (const TriangleMesh& result : results)
              chamfer.push_back(
                  surfaceDistance(result, fitter->measuredTarget(), kDistanceSamples).chamfer);
            return chamfer;
          });
      for (const FoldSuggestion& suggestion : found_) {
        const FoldRecord& fold = suggestion.folds.front();
        offered_.push_back({fold.seed, fold.grabbed, fold.target});
      }
      frame.suggestions = offered_;
    }
  }

  // The distance of the committed design, measured again when it changes.
  if (replaying_ || !fitter_) return;
  if (isReady(measuringFound_)) foundChamfer_ = measuringFound_.get();
  if (isReady(measuring_)) measured_ = measuring_.get();
  const bool current = measured_ && measured_->session == doc.session.get() &&
                       measured_->revision == doc.session->designRevision();
  if (!current && !measuring_.valid()) {
    measuring_ = std::async(
        std::launch::async, [fitter = fitter_, mesh = meshOf(doc.session->fixed()),
                             session = static_cast<const void*>(doc.session.get()),
                             revision = doc.session->designRevision(), nice = searchNice_] {
          measureAtNice(nice);
          return Measured{revision, session,
                          surfaceDistance(mesh, fitter->measuredTarget(), kDistanceSamples)};
        });
  }
  measuredCurrent_ = current;
}

bool StudioTarget::hasNews() const {
  if (isReady(loading_) || isReady(measuring_) || isReady(measuringFound_) || isReady(revising_))
    return true;
  // A search asked once its target is there waits for the load, not the worker.
  return searching_ && !loading_.valid() && worker_ && !worker_->busy();
}

const TriangleMesh* StudioTarget::offeredResult(const InteractionCore& core) const {
  const SuggestedFold* offer = core.offeredFold();
  if (!offer) return nullptr;
  for (std::size_t i = 0; i < offered_.size() && i < moved_.size(); ++i)
    if (offered_[i] == *offer) return &moved_[i];
  return nullptr;
}

std::string StudioTarget::distanceLine() const {
  if (loading_.valid()) return "loading the target " + loadingPath_ + " ...";
  if (!loadError_.empty()) return loadError_;
  if (!fitter_) return "target: none";
  if (replaying_) return "target: " + path_;
  if (!measured_) return "measuring the distance to the target ...";
  const SurfaceDistance& d = measured_->distance;
  return (measuredCurrent_ ? "" : "(measuring) ") +
         distanceText(d.hausdorff, d.chamfer, d.diagonal);
}

std::string StudioTarget::suggestionLine(const InteractionCore& core) const {
  if (searching_) return "searching for the next fold ...";
  if (const SuggestedFold* offer = core.offeredFold()) {
    std::string line = "suggestion " + std::to_string(core.offerIndex() + 1) + " of " +
                       std::to_string(core.offerCount());
    // The design's Chamfer as the distance line gives it, and what this fold would make it.
    for (std::size_t i = 0; i < offered_.size() && i < found_.size(); ++i) {
      if (!(offered_[i] == *offer)) continue;
      line += ": Chamfer " + (measured_ && measuredCurrent_
                                  ? millimetresText(measured_->distance.chamfer)
                                  : std::string("..."));
      line += " -> " + (i < foundChamfer_.size() ? millimetresText(foundChamfer_[i])
                                                 : std::string("measuring ..."));
    }
    return line;
  }
  return answerNote_.empty() ? startNote_ : answerNote_;
}

void StudioTarget::documentReplaced() {
  if (revising_.valid()) dropRevision("");  // the start it revised is gone
  if (worker_) worker_->cancel();
  searching_ = false;
  requestSession_ = nullptr;
  answerNote_.clear();
  found_.clear();
  moved_.clear();
  offered_.clear();
  retireFound();
  // A measure of the old design must not pass for one of the new (its session may share the
  // address): it finishes off the frame, unread.
  retireMeasuring();
  measured_.reset();
  measuredCurrent_ = false;
}

void StudioTarget::dropRevision(const std::string& note) {
  if (reviseCancel_) *reviseCancel_ = true;
  if (revising_.valid()) retiredRevisions_.push_back(std::move(revising_));
  revising_ = {};
  reviseCancel_.reset();
  startNote_ = note;
}

void StudioTarget::reviseStart(const session::Document& doc) {
  if (replaying_ || !fitter_) return;
  dropRevision("choosing the start as fit would ...");
  reviseSession_ = doc.session.get();
  reviseRevision_ = doc.session->designRevision();
  reviseCancel_ = std::make_shared<std::atomic<bool>>(false);
  revising_ = std::async(std::launch::async, [fitter = fitter_, open = doc.surface,
                                              cancel = reviseCancel_, nice = searchNice_] {
    pthread_setname_np(pthread_self(), "cf-start");
    Revised revised;
    runAtSearchNice(nice, [&] {
      try {
        Design design = fitStartForTarget(fitter->target(), cancel.get());
        const auto* generated = std::get_if<GeneratedSurface>(&design.surface);
        revised.kind = generated ? generated->generator : "a sheet placed on the target";
        if (!sameStart(design.surface, open)) revised.design = std::move(design);
      } catch (const std::exception& e) {
        revised.error = e.what();
      }
    });
    return revised;
  });
}

std::optional<Design> StudioTarget::takeRevisedStart(const session::Document& doc, bool busy) {
  if (!revising_.valid()) return std::nullopt;
  // The designer went on from the sheet open (a fold, an undo, a Suggest): theirs is kept, and
  // the revision, of no use now, stops.
  const bool untouched = reviseSession_ == doc.session.get() &&
                         reviseRevision_ == doc.session->designRevision() &&
                         requestSession_ == nullptr && !busy;
  if (!untouched) {
    dropRevision("");
    return std::nullopt;
  }
  if (doc.session->dragging() || !isReady(revising_)) return std::nullopt;  // after the drag
  Revised revised = revising_.get();
  revising_ = {};
  reviseCancel_.reset();
  if (!revised.error.empty()) {
    startNote_ = "the start fit would choose: " + revised.error;
    return std::nullopt;
  }
  startNote_ = revised.design ? "start: " + revised.kind + ", as fit chooses it" : "";
  return std::move(revised.design);
}

}  // namespace curvefold::studio
