#include "engine/geometry/fold_session.hpp"

#include <string>

#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/validate.hpp"

#include <glm/geometric.hpp>

namespace curvefold {

Sheet applyFold(const Sheet& sheet, const FoldRecord& fold) {
  VertexInsertion grab = insertVertexAt(sheet, fold.seed);
  if (fold.moreSeeds.empty()) return reflect(grab.sheet, grab.vertex, fold.plane).sheet;
  const std::vector<VertexIndex> more = verticesAtDevelopment(grab.sheet, fold.moreSeeds);
  return reflect(grab.sheet, buildAdjacency(grab.sheet), grab.vertex, fold.plane,
                 sheetEpsilon(grab.sheet), more)
      .sheet;
}

Sheet replayFolds(Sheet initial, const std::vector<FoldRecord>& folds) {
  for (std::size_t i = 0; i < folds.size(); ++i) {
    try {
      initial = applyFold(initial, folds[i]);
    } catch (const InvalidSheet& error) {
      throw InvalidSheet("fold " + std::to_string(i + 1) + ": " + error.what());
    }
  }
  return initial;
}

FoldSession::FoldSession(Sheet initial)
    : initial_(std::make_shared<const Sheet>(std::move(initial))),
      epsilon_(sheetEpsilon(*initial_)) {
  setFixed(*initial_);
  keyframes_.push_back(initial_);
}

void FoldSession::restartFrom(Sheet initial) {
  initial_ = std::make_shared<const Sheet>(std::move(initial));
  epsilon_ = sheetEpsilon(*initial_);
  dragging_ = folded_ = sliver_ = grabInserted_ = previewing_ = false;
  grabVertex_ = kNoIndex;
  history_.clear();
  undoPoint_.reset();  // another initial sheet
  applied_ = 0;
  keyframes_.assign(1, initial_);
  symmetric_.reset();
  previewFolder_.reset();
  setFixed(*initial_);
  ++designRevision_;
}

void FoldSession::setFixed(Sheet sheet) {
  fixed_ = std::move(sheet);
  temporal_ = fixed_;
  fixedChanged();
}

void FoldSession::fixedChanged() {
  fixedAdjacency_ = buildAdjacency(fixed_);
  ++fixedRevision_;
}

glm::dvec3 FoldSession::beginDrag(const SurfacePoint& point) {
  return beginDragAtDevelopment(developmentOf(fixed_, point), point.triangle);
}

glm::dvec3 FoldSession::beginDragNear(const glm::dvec3& p) {
  return beginDrag(closestSurfacePoint(fixed_, p));
}

// The grabbed point is inserted into the fixed sheet itself (taken back exactly on cancel), so a
// drag holds two sheets, fixed and temporal, not three.
glm::dvec3 FoldSession::beginDragAtDevelopment(const glm::dvec2& seed, TriangleIndex triangle) {
  cancel();
  // What the session knows spares the insertion its scans of every triangle (the same result).
  const InsertionHints hints{epsilon_ / kRelativeEpsilon, triangle, &fixedAdjacency_.triangles};
  grabVertex_ = insertVertexInPlace(fixed_, seed, &grabUndo_, hints);
  grabInserted_ = fixed_.vertexCount() != grabUndo_.vertexCount;
  if (grabInserted_) {
    // The adjacency before is kept for a cancel, which takes the insertion back exactly; the one
    // after is patched where the insertion touched it. temporal_, equal to fixed_ between drags,
    // takes the same few changes: a grab costs no scan and no copy of the sheet.
    std::swap(fixedAdjacency_, adjacencyBeforeGrab_);
    adjacencyAfterInsertion(adjacencyBeforeGrab_, fixed_, grabUndo_, fixedAdjacency_);
    ++fixedRevision_;
    for (const auto& [t, old] : grabUndo_.rewritten) temporal_.triangles[t] = fixed_.triangles[t];
    temporal_.positions.insert(temporal_.positions.end(),
                               fixed_.positions.begin() + grabUndo_.vertexCount,
                               fixed_.positions.end());
    temporal_.development.insert(temporal_.development.end(),
                                 fixed_.development.begin() + grabUndo_.vertexCount,
                                 fixed_.development.end());
    temporal_.triangles.insert(temporal_.triangles.end(),
                               fixed_.triangles.begin() + grabUndo_.triangleCount,
                               fixed_.triangles.end());
    if (grabUndo_.tagsChanged) temporal_.tags = fixed_.tags;
  }
  grabSeed_ = seed;
  grabbed_ = fixed_.positions[grabVertex_];
  target_ = grabbed_;
  workspace_.clear();
  dragging_ = true;
  folded_ = false;
  return grabbed_;
}

const ReflectionChanges& FoldSession::updateDrag(const glm::dvec3& target) {
  if (!dragging_) throw std::logic_error("updateDrag without a drag in progress");
  checkWithinReach(target, grabbed_, epsilon_ / kRelativeEpsilon, "drag target");
  target_ = target;
  // A drag shorter than the smallest feature is no fold: its bisector would lie within the
  // on-plane tolerance of much of the sheet and crease it everywhere (a target equal to the
  // grabbed point is a no-op, not an error).
  folded_ = glm::distance(target, grabbed_) > minimumDrag();
  sliver_ = false;
  if (previewing_) ++previewRevision_;
  previewing_ = false;
  // No fold at this target: the temporal sheet is the fixed one again.
  auto unfolded = [&]() -> const ReflectionChanges& {
    folded_ = false;
    workspace_.restore(fixed_, temporal_);
    workspace_.clear();
    return workspace_.changes();
  };
  if (!folded_) return unfolded();
  plane_ = bisectorPlane(grabbed_, target);
  workspace_.reapply(fixed_, fixedAdjacency_, grabVertex_, plane_, epsilon_, temporal_);
  // A cut that leaves a piece under validate()'s floor even after the workspace's plane shifts (an
  // oblique plane across a long, thin triangle, far from its corners) folds nothing at this
  // target: the sheet stays as it is, never invalid, and a commit here is refused with the reason.
  const double floor = ValidationOptions{}.relativeDegenerateHeight * (epsilon_ / kRelativeEpsilon);
  if (workspace_.changes().thinnestCut < floor) {
    sliver_ = true;
    return unfolded();
  }
  if (previewFolder_) {
    preview_ = temporal_;
    previewReflected_ = workspace_.reflectedTriangles(fixedAdjacency_);
    try {
      previewFolder_->previewImages(fixed_, preview_,
                                    FoldRecord{grabSeed_, plane_, grabbed_, target_, 0, {}},
                                    previewReflected_);
      previewing_ = true;
    } catch (const InvalidSheet&) {
      previewing_ = false;  // an image this sheet cannot make: the commit will say
    }
    ++previewRevision_;
  }
  return workspace_.changes();
}

const std::vector<TriangleIndex>& FoldSession::reflectedTriangles() const {
  static const std::vector<TriangleIndex> none;
  if (!dragging_ || !folded_) return none;
  if (previewing_) return previewReflected_;
  return workspace_.reflectedTriangles(fixedAdjacency_);
}

bool FoldSession::commit() {
  refusal_.clear();
  if (!dragging_) return false;
  if (!folded_) {
    if (sliver_)
      refusal_ =
          "the fold was not kept: its plane cuts a piece thinner than the degenerate "
          "floor from a thin triangle; a target a little away gives a sound fold";
    cancel();
    return false;
  }
  // What the grab and the fold made must pass validate()'s triangle rules before it is kept: a
  // plane just outside the on-plane tolerance through a thin triangle can leave a sliver.
  std::vector<TriangleIndex> made = workspace_.changes().rewrittenTriangles;
  for (const auto& [t, old] : grabUndo_.rewritten) made.push_back(t);
  const std::size_t firstMade = grabInserted_ ? grabUndo_.triangleCount : temporal_.triangleCount();
  for (std::size_t t = std::min(firstMade, workspace_.changes().firstNewTriangle);
       t < temporal_.triangleCount(); ++t)
    made.push_back(static_cast<TriangleIndex>(t));
  try {
    validateTriangles(temporal_, made, epsilon_ / kRelativeEpsilon);
  } catch (const InvalidSheet& e) {
    refusal_ = std::string("the fold was not kept: ") + e.what() +
               "; a target a little away gives a sound fold";
    cancel();
    return false;
  }
  // The images follow, through the sheet as it was before the fold (fixed_), onto the folded one;
  // an image the design could not record refuses the whole fold, before anything is kept.
  const FoldRecord record{grabSeed_, plane_, grabbed_, target_, 0, {}};
  SymmetricFolder::Result images;
  if (symmetric_) {
    try {
      images = symmetric_->applyImages(fixed_, temporal_, record);
    } catch (const InvalidSheet& e) {
      refusal_ = std::string("the fold was not kept: ") + e.what();
      temporal_ = fixed_;  // the images changed it past what the workspace restores
      cancel();
      return false;
    }
  }
  dragging_ = false;
  folded_ = false;
  previewing_ = false;
  historyChangesFrom(applied_);
  history_.resize(applied_);
  // Keyframe k holds the sheet after k * interval folds; later ones belong to the dropped redo.
  if (keyframes_.size() > applied_ / kKeyframeInterval + 1)
    keyframes_.resize(applied_ / kKeyframeInterval + 1);
  history_.push_back(record);
  ++applied_;
  ++designRevision_;
  lastSkipped_ = lastOverlapping_ = 0;
  std::swap(fixed_, temporal_);
  if (symmetric_) {
    std::uint32_t group = 0;
    for (std::size_t i = 0; i + 1 < history_.size(); ++i)
      group = std::max(group, history_[i].group);
    history_.back().group = group + 1;
    for (FoldRecord image : images.applied) {
      image.group = group + 1;
      history_.push_back(image);
      ++applied_;
    }
    lastSkipped_ = images.skipped;
    lastOverlapping_ = images.overlapping;
  }
  temporal_ = fixed_;  // reuses the old storage; a commit pays for the sheet anyway (adjacency)
  fixedChanged();
  addKeyframes();
  return true;
}

void FoldSession::addKeyframes() {
  // Keyframe k is the sheet after k * interval folds; a group of images may step past one.
  while (keyframes_.size() * kKeyframeInterval <= applied_)
    keyframes_.push_back(
        std::make_shared<const Sheet>(keyframes_.size() * kKeyframeInterval == applied_
                                          ? fixed_
                                          : sheetAfter(keyframes_.size() * kKeyframeInterval)));
}

void FoldSession::applyRecords(const std::vector<FoldRecord>& folds) {
  cancel();
  if (folds.empty()) return;
  historyChangesFrom(applied_);
  history_.resize(applied_);
  if (keyframes_.size() > applied_ / kKeyframeInterval + 1)
    keyframes_.resize(applied_ / kKeyframeInterval + 1);
  Sheet sheet = fixed_;
  for (const FoldRecord& fold : folds) {
    sheet = applyFold(sheet, fold);
    history_.push_back(fold);
    // A keyframe due here is this sheet: addKeyframes would fold it again from the last one.
    if (history_.size() == keyframes_.size() * kKeyframeInterval)
      keyframes_.push_back(std::make_shared<const Sheet>(sheet));
  }
  applied_ = history_.size();
  ++designRevision_;
  setFixed(std::move(sheet));
  addKeyframes();
}

void FoldSession::setSymmetry(const Symmetry& symmetry) {
  symmetric_ = symmetry.kind == Symmetry::Kind::None
                   ? nullptr
                   : std::make_shared<const SymmetricFolder>(initial_, symmetry);
}

const Symmetry* FoldSession::symmetry() const {
  return symmetric_ ? &symmetric_->symmetry() : nullptr;
}

void FoldSession::setImagePreview(std::shared_ptr<const SymmetricFolder> folder) {
  previewFolder_ = std::move(folder);
  if (previewing_) ++previewRevision_;
  previewing_ = false;  // from the next update
}

void FoldSession::cancel() {
  previewing_ = false;
  // temporal_ back to fixed_ as it was before the grab, at the cost of what the drag changed.
  if (dragging_) workspace_.restore(fixed_, temporal_);
  workspace_.clear();
  if (dragging_ && grabInserted_) {
    undoInsertion(temporal_, grabUndo_);
    undoInsertion(fixed_, grabUndo_);
    std::swap(fixedAdjacency_, adjacencyBeforeGrab_);
    ++fixedRevision_;
  }
  dragging_ = false;
  folded_ = false;
  sliver_ = false;
  grabInserted_ = false;
}

SessionMemory FoldSession::memoryUse() const {
  SessionMemory memory{sheetBytes(fixed_), sheetBytes(temporal_),
                       adjacencyBytes(fixedAdjacency_) + adjacencyBytes(adjacencyBeforeGrab_),
                       workspace_.memoryBytes(), 0};
  for (std::size_t k = 1; k < keyframes_.size(); ++k) memory.history += sheetBytes(*keyframes_[k]);
  if (undoPoint_)
    memory.history += sheetBytes(undoPoint_->sheet) + adjacencyBytes(undoPoint_->adjacency);
  return memory;
}

Sheet FoldSession::sheetAfter(std::size_t foldCount) const {
  const std::size_t keyframe = std::min(foldCount / kKeyframeInterval, keyframes_.size() - 1);
  Sheet sheet = *keyframes_[keyframe];
  for (std::size_t i = keyframe * kKeyframeInterval; i < foldCount; ++i)
    sheet = applyFold(sheet, history_[i]);
  return sheet;
}

bool FoldSession::undo() {
  cancel();
  if (!canUndo()) return false;
  const std::uint32_t group = history_[applied_ - 1].group;
  --applied_;
  while (group != 0 && applied_ > 0 && history_[applied_ - 1].group == group) --applied_;
  ++designRevision_;
  fixedFromHistory();
  return true;
}

std::size_t FoldSession::undoTo(std::size_t foldCount) {
  if (applied_ <= foldCount) return 0;  // as the loop of undo() calls: not even a cancel
  cancel();
  const std::size_t before = applied_;
  while (applied_ > foldCount) {
    const std::uint32_t group = history_[applied_ - 1].group;
    --applied_;
    while (group != 0 && applied_ > 0 && history_[applied_ - 1].group == group) --applied_;
  }
  ++designRevision_;
  fixedFromHistory();
  return before - applied_;
}

void FoldSession::fixedFromHistory() {
  // The sheet after the same folds is the same bit for bit (the keyframes and records before the
  // point stand: historyChangesFrom), and so is its adjacency; copies cost far less than the
  // folds replayed and the adjacency built again.
  if (undoPoint_ && undoPoint_->foldCount == applied_) {
    fixed_ = undoPoint_->sheet;
    temporal_ = fixed_;
    fixedAdjacency_ = undoPoint_->adjacency;
    ++fixedRevision_;
    return;
  }
  setFixed(sheetAfter(applied_));
  undoPoint_ = UndoPoint{applied_, fixed_, fixedAdjacency_};
}

void FoldSession::historyChangesFrom(std::size_t fold) {
  // Today the folds fall below the point only through undo and undoTo, which move it, or
  // restartFrom, which drops it, so a commit keeps every record before it; this keeps the point
  // right should that change.
  if (undoPoint_ && undoPoint_->foldCount > fold) undoPoint_.reset();
}

bool FoldSession::redo() {
  cancel();
  if (!canRedo()) return false;
  const std::uint32_t group = history_[applied_].group;
  Sheet sheet = applyFold(fixed_, history_[applied_++]);
  while (group != 0 && applied_ < history_.size() && history_[applied_].group == group)
    sheet = applyFold(sheet, history_[applied_++]);
  setFixed(std::move(sheet));
  ++designRevision_;
  addKeyframes();
  return true;
}

}  // namespace curvefold
