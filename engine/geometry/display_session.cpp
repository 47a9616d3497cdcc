#include "engine/geometry/display_session.hpp"

#include "engine/geometry/planar_simplification.hpp"

namespace curvefold {

void DisplaySession::rebuild(const FoldSession& source) {
  ++generation_;
  source_ = &source;
  designRevision_ = source.designRevision();
  baseFolds_ = source.foldCount();
  target_.reset();
  coarse_.reset();
  if (!simplify_) return;
  try {
    coarse_ = std::make_unique<FoldSession>(simplifyPlanar(source.fixed()).sheet);
    // A symmetric session's drag shows its images, made on the coarse sheet (cheap there).
    coarse_->setImagePreview(source.symmetricFolder());
  } catch (const std::exception&) {
    coarse_.reset();  // draw the source's own sheet
  }
}

void DisplaySession::follow(const FoldSession& source) {
  if (&source != source_) {
    rebuild(source);
  } else if (source.designRevision() != designRevision_) {
    // One commit of the drag followed here is made here too; anything else starts afresh.
    bool committed = false;
    if (coarse_ && coarse_->dragging() && !source.dragging() &&
        source.designRevision() == designRevision_ + 1 &&
        source.foldCount() == baseFolds_ + coarse_->foldCount() + 1 &&
        source.folds()[source.foldCount() - 1].seed == grabSeed_) {
      try {
        coarse_->updateDrag(source.folds()[source.foldCount() - 1].target);
        committed = coarse_->commit();
      } catch (const std::exception&) {
        committed = false;
      }
    }
    if (committed) {
      designRevision_ = source.designRevision();
      target_.reset();
    } else {
      rebuild(source);
    }
  }
  if (!coarse_) return;
  try {
    followDrag(source);
  } catch (const std::exception&) {
    coarse_.reset();
    ++generation_;
  }
}

void DisplaySession::followDrag(const FoldSession& source) {
  if (!source.dragging()) {
    if (coarse_->dragging()) coarse_->cancel();
    target_.reset();
    return;
  }
  if (!coarse_->dragging() || source.grabbedSeed() != grabSeed_) {
    // Grab where the source's grabbed vertex is (it may have snapped to a vertex near the seed):
    // that point is a vertex of the coarse sheet too, or is inserted at the same place.
    coarse_->beginDragAtDevelopment(source.fixed().development[source.grabbedVertex()]);
    grabSeed_ = source.grabbedSeed();
    target_.reset();
  }
  const glm::dvec3 target = source.hasPlane() ? source.dragTarget() : coarse_->grabbedPoint();
  if (target_ != target) {
    coarse_->updateDrag(target);
    target_ = target;
  }
}

const Sheet& DisplaySession::sheet() const {
  return shownSession().current();
}

std::span<const TriangleIndex> DisplaySession::reflectedTriangles() const {
  return shownSession().reflectedTriangles();
}

const FoldSession& DisplaySession::shownSession() const {
  if (coarse_) return *coarse_;
  if (!source_) throw std::logic_error("DisplaySession used before follow()");
  return *source_;
}

}  // namespace curvefold
