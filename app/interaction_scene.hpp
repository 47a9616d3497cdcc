// What the renderer shows of an interaction (DESIGN.md 7), for every live or replayed view: the
// displayed sheet in the world, the reflected part tinted, the grabbed handle and its start, the
// plane disk while a drag folds, the hover highlight, and optionally both hands.
#pragma once

#include <glm/mat4x4.hpp>

#include "engine/render/scene.hpp"
#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"

namespace curvefold {

glm::mat4 matrixOf(const Pose& pose);

struct InteractionSceneOptions {
  bool creasePatternPanel = false;
  bool handMarkers = false;  // both hands as markers (replays); the desktop's mouse needs none
};

Scene sceneForInteraction(const InteractionCore& core, const InputFrame& input,
                          const Camera& camera, const Ground& ground,
                          const InteractionSceneOptions& options = {});

}  // namespace curvefold
