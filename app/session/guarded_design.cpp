#include "app/session/guarded_design.hpp"

#include <stdexcept>

#include "app/session/design_check.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/validate.hpp"

namespace curvefold::session {

GuardedDesign::GuardedDesign(Design design, std::string name) : name_(std::move(name)) {
  surface_ = design.surface;
  symmetry_ = design.symmetry;
  session_ = std::make_unique<FoldSession>(initialSheet(design, name_));
  session_->applyRecords(design.folds);
  if (!symmetry_.empty()) session_->setSymmetry(parseSymmetry(symmetry_, session_->initial()));
}

void GuardedDesign::owns(const Lock& lock) const {
  if (lock.design_ != this || !lock.lock_.owns_lock())
    throw std::logic_error("GuardedDesign: used under another design's lock");
}

Design GuardedDesign::design(const Lock& lock) const {
  owns(lock);
  const auto& history = session_->folds();
  return Design{surface_,
                {history.begin(), history.begin() + std::ptrdiff_t(session_->foldCount())},
                symmetry_};
}

FoldSession& GuardedDesign::session(const Lock& lock) {
  owns(lock);
  return *session_;
}

const FoldSession& GuardedDesign::session(const Lock& lock) const {
  owns(lock);
  return *session_;
}

std::shared_ptr<const Sheet> GuardedDesign::snapshot(const Lock& lock) const {
  owns(lock);
  if (!snapshot_ || snapshotRevision_ != session_->designRevision()) {
    snapshot_ = std::make_shared<const Sheet>(session_->fixed());
    snapshotRevision_ = session_->designRevision();
  }
  return snapshot_;
}

FoldResult GuardedDesign::fold(const Lock& lock, const glm::dvec3& grab, const glm::dvec3& to) {
  owns(lock);
  const std::size_t before = session_->foldCount();
  const glm::dvec3 grabbed = session_->beginDragNear(grab);
  session_->updateDrag(to);
  FoldResult result;
  result.grabbed = {grabbed.x, grabbed.y, grabbed.z};
  const ReflectionPlane plane = session_->hasPlane() ? session_->plane() : ReflectionPlane{};
  if (!session_->commit()) {
    if (!session_->refusal().empty()) throw std::invalid_argument(session_->refusal());
    result.triangles = session_->fixed().triangleCount();
    return result;
  }
  // The same check as the command line's fold.
  ValidationOptions tolerance;
  tolerance.relativeLengthTolerance =
      isometryTolerance(session_->initial()) / sheetSize(session_->fixed());
  try {
    validate(session_->fixed(), tolerance);
  } catch (...) {
    session_->undo();
    throw;
  }
  result.folded = true;
  result.planePoint = {plane.point.x, plane.point.y, plane.point.z};
  result.planeNormal = {plane.normal.x, plane.normal.y, plane.normal.z};
  result.triangles = session_->fixed().triangleCount();
  result.images = session_->foldCount() - before - 1;
  result.notes = imageNotes(session_->lastSkippedImages(), session_->lastOverlappingImages());
  return result;
}

}  // namespace curvefold::session
