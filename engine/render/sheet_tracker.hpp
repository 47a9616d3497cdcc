// Turns a FoldSession's state into SceneRenderer::markSheet* calls, frame by frame.
//
// During one drag every temporal sheet is the grab sheet plus that update's ReflectionChanges
// (updateDrag restores the previous changes, then applies new ones). So the sheet shown now
// differs from the one shown at the last call only in the union of the two change records,
// however many updates happened in between. Anything else (a new drag, commit, cancel, undo,
// redo) replaces the sheet wholesale.
#pragma once

#include <glm/vec3.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/render/scene_renderer.hpp"

namespace curvefold {

class SessionSheetTracker {
 public:
  // Call once per frame before building the scene from session.current().
  void update(const FoldSession& session, SceneRenderer& renderer);

 private:
  bool seen_ = false;
  bool dragging_ = false;
  std::uint64_t fixedRevision_ = 0;
  glm::dvec3 grabbed_{0.0};
  VertexIndex grabbedVertex_ = kNoIndex;
  ReflectionChanges last_;
};

}  // namespace curvefold
