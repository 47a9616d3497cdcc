#include "engine/render/sheet_tracker.hpp"

namespace curvefold {
namespace {

bool sameChanges(const ReflectionChanges& a, const ReflectionChanges& b) {
  return a.firstNewVertex == b.firstNewVertex && a.firstNewTriangle == b.firstNewTriangle &&
         a.movedVertices == b.movedVertices && a.rewrittenTriangles == b.rewrittenTriangles;
}

}  // namespace

void SessionSheetTracker::update(const FoldSession& source, SceneRenderer& renderer) {
  display_.follow(source);
  const FoldSession& session = display_.shownSession();
  const bool dragging = session.dragging();
  const bool sameBase = seen_ && display_.generation() == generation_ && dragging == dragging_ &&
                        session.fixedRevision() == fixedRevision_ &&
                        (!dragging || (session.grabbedPoint() == grabbed_ &&
                                       session.grabbedVertex() == grabbedVertex_));
  if (!sameBase) {
    renderer.markSheetReplaced();
    seen_ = true;
    generation_ = display_.generation();
    dragging_ = dragging;
    fixedRevision_ = session.fixedRevision();
    grabbed_ = session.grabbedPoint();
    grabbedVertex_ = session.grabbedVertex();
    last_ = dragging ? session.lastChanges() : ReflectionChanges{};
    previewRevision_ = session.previewRevision();
    return;
  }
  if (!dragging) return;  // the fixed sheet has not changed
  if (session.previewingImages() || previewRevision_ != session.previewRevision()) {
    // A drag's previewed images are remade whole at each update (on a coarse sheet).
    if (previewRevision_ != session.previewRevision()) renderer.markSheetReplaced();
    previewRevision_ = session.previewRevision();
    last_ = session.lastChanges();
    return;
  }
  const ReflectionChanges& now = session.lastChanges();
  if (sameChanges(now, last_)) return;
  renderer.markSheetChanged(last_);  // put back what the previous update changed
  renderer.markSheetChanged(now);
  last_ = now;
}

void SessionSheetTracker::describe(SceneSheet& sheet) const {
  if (!seen_) return;
  sheet.sheet = &display_.sheet();
  sheet.reflectedTriangles = display_.reflectedTriangles();
}

}  // namespace curvefold
