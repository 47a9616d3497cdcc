#include "app/studio_target.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/surfaces/obj_surface.hpp"

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

}  // namespace

StudioTarget::StudioTarget(bool replaying, double suggestionSeconds)
    : replaying_(replaying), suggestionSeconds_(suggestionSeconds) {}

// The worker and the measures still running are waited for here, when the studio ends (each
// stops at its next check, or within a measure).
StudioTarget::~StudioTarget() = default;

void StudioTarget::retireMeasuring() {
  // A future of std::async waits for its task when destroyed: kept until it is ready.
  if (measuring_.valid()) retired_.push_back(std::move(measuring_));
  measuring_ = {};
}

void StudioTarget::reapRetired() {
  std::erase_if(retired_, [](const std::future<Measured>& f) {
    return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  });
}

void StudioTarget::load(const std::string& path, const session::Document& doc) {
  std::shared_ptr<const FoldFitter> fitter;
  try {
    fitter = std::make_shared<const FoldFitter>(readObjMesh(path));
    fitter->checkAgainst(doc.session->initial());
  } catch (const InvalidTarget& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  // The old target's search (if any) is abandoned and its measure left to finish off the frame.
  retireMeasuring();
  fitter_ = std::move(fitter);
  path_ = path;
  if (!replaying_) {
    if (worker_)
      worker_->retarget(fitter_);
    else
      worker_ = std::make_unique<SuggestionWorker>(fitter_, suggestionSeconds_);
  }
  measured_.reset();
  searching_ = false;
  answerNote_.clear();
  found_.clear();
  moved_.clear();
  offered_.clear();
}

const TriangleMesh* StudioTarget::mesh() const {
  return fitter_ ? &fitter_->target() : nullptr;
}

void StudioTarget::suggest(const session::Document& doc) {
  if (!fitter_) throw std::runtime_error("no target to suggest toward: load one first");
  requestSession_ = doc.session.get();
  requestRevision_ = doc.session->designRevision();
  searching_ = true;
  answerNote_.clear();
  if (replaying_) return;  // the recording brings what was found
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
  if (searching_ && !sameDesign) {
    // Folded, undone or replaced while searching: what comes is for another design.
    if (worker_) worker_->cancel();
    searching_ = false;
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
      for (const FoldSuggestion& suggestion : found_) {
        const FoldRecord& fold = suggestion.folds.front();
        offered_.push_back({fold.seed, fold.grabbed, fold.target});
      }
      frame.suggestions = offered_;
    }
  }

  // The distance of the committed design, measured again when it changes.
  if (replaying_ || !fitter_) return;
  if (measuring_.valid() &&
      measuring_.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
    measured_ = measuring_.get();
  const bool current = measured_ && measured_->session == doc.session.get() &&
                       measured_->revision == doc.session->designRevision();
  if (!current && !measuring_.valid()) {
    measuring_ = std::async(std::launch::async, [fitter = fitter_,
                                                 mesh = meshOf(doc.session->fixed()),
                                                 session =
                                                     static_cast<const void*>(doc.session.get()),
                                                 revision = doc.session->designRevision()] {
      return Measured{revision, session, surfaceDistance(mesh, fitter->target(), kDistanceSamples)};
    });
  }
  measuredCurrent_ = current;
}

const TriangleMesh* StudioTarget::offeredResult(const InteractionCore& core) const {
  const SuggestedFold* offer = core.offeredFold();
  if (!offer) return nullptr;
  for (std::size_t i = 0; i < offered_.size() && i < moved_.size(); ++i)
    if (offered_[i] == *offer) return &moved_[i];
  return nullptr;
}

std::string StudioTarget::distanceLine() const {
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
    for (std::size_t i = 0; i < offered_.size() && i < found_.size(); ++i)
      if (offered_[i] == *offer)
        line += ": Chamfer about " + millimetresText(found_[i].before) + " -> " +
                millimetresText(found_[i].after);
    return line;
  }
  return answerNote_;
}

void StudioTarget::documentReplaced() {
  if (worker_) worker_->cancel();
  searching_ = false;
  requestSession_ = nullptr;
  answerNote_.clear();
  found_.clear();
  moved_.clear();
  offered_.clear();
  // A measure of the old design must not pass for one of the new (its session may share the
  // address): it finishes off the frame, unread.
  retireMeasuring();
  measured_.reset();
  measuredCurrent_ = false;
}

}  // namespace curvefold::studio
