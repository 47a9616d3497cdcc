// Turns a FoldSession's state into SceneRenderer::markSheet* calls, frame by frame. What is drawn
// is the session's DisplaySession (planar regions merged: lavapipe's cost is per triangle), so
// the records below are the coarse session's.
//
// During one drag every temporal sheet is the grab sheet plus that update's ReflectionChanges
// (updateDrag restores the previous changes, then applies new ones). So the sheet shown now
// differs from the one shown at the last call only in the union of the two change records,
// however many updates happened in between. Anything else (a new drag, commit, cancel, undo,
// redo) replaces the sheet wholesale.
#pragma once

#include <glm/vec3.hpp>

#include "engine/geometry/display_session.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/render/scene_renderer.hpp"

namespace curvefold {

class SessionSheetTracker {
 public:
  // simplify = false draws every triangle of the session's sheet.
  explicit SessionSheetTracker(bool simplify = true) : display_(simplify) {}

  // Call once per frame before building the scene from session.current().
  void update(const FoldSession& session, SceneRenderer& renderer);
  // Points the scene at the sheet to draw and its reflected part (left as they are before the
  // first update).
  void describe(SceneSheet& sheet) const;
  const DisplaySession& display() const { return display_; }

 private:
  DisplaySession display_;
  bool seen_ = false;
  std::uint64_t generation_ = 0;
  bool dragging_ = false;
  std::uint64_t fixedRevision_ = 0;
  glm::dvec3 grabbed_{0.0};
  VertexIndex grabbedVertex_ = kNoIndex;
  ReflectionChanges last_;
  std::uint64_t previewRevision_ = 0;
};

}  // namespace curvefold
