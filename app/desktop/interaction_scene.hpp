// What the renderer shows of an interaction (docs/design.md 7), for every live or replayed view:
// the displayed sheet in the world, the reflected part tinted, the grabbed handle and its start,
// the plane disk while a drag folds, the hover highlight, and optionally both hands.
#pragma once

#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>

#include "engine/geometry/triangle_mesh.hpp"
#include "engine/render/scene.hpp"
#include "engine/render/scene_renderer.hpp"
#include "engine/render/sheet_tracker.hpp"
#include "interaction/hand_input.hpp"
#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"

namespace curvefold::desktop {

glm::mat4 matrixOf(const Pose& pose);

// The crease pattern panel of a session's committed design, rebuilt only when the design changes
// (a commit, undo or redo; a grab's vertex changes nothing drawn): building it walks every edge
// (78 to 113 ms at 100k triangles), which the desktop window used to pay every frame. The desktop
// window, the headset's held card and rendered replays share it.
class CreasePatternCache {
 public:
  const CreasePatternPanel& panelFor(const FoldSession& session, const SceneColors& colors);
  std::size_t builds() const { return builds_; }

 private:
  const FoldSession* session_ = nullptr;
  const Sheet* initial_ = nullptr;
  std::uint64_t revision_ = 0;
  std::size_t builds_ = 0;
  CreasePatternPanel panel_;
};

// The renderer's copy of what sceneForInteraction draws, frame by frame: the session's sheet
// through a SessionSheetTracker (its merged display sheet), or, while the core simulates, the
// simulated sheet, which moves everywhere each frame: its vertices are uploaded again, its
// triangles only when a simulation starts. Leaving the simulation starts the tracker afresh, so
// the design comes back whole.
class InteractionSheetTracker {
 public:
  explicit InteractionSheetTracker(bool simplify = true)
      : simplify_(simplify), tracker_(simplify) {}
  // Once per frame, before the scene is built.
  void update(const InteractionCore& core, SceneRenderer& renderer);
  // After sceneForInteraction: the sheet to draw (the tracker's, unless simulating). While
  // simulating with strainColours (the panel's "strain"), each vertex coloured by the largest
  // strain of its edges (LiveSimulation::vertexStrain), viridis from 0 to the sheet's largest;
  // the colours live in the tracker until the next describe.
  void describe(const InteractionCore& core, SceneSheet& sheet, bool strainColours = false);

 private:
  bool simplify_;
  SessionSheetTracker tracker_;
  bool simulated_ = false;
  // The simulation last drawn and the design it was made from: another is a new sheet.
  const LiveSimulation* simulation_ = nullptr;
  std::uint64_t simulationRevision_ = 0;
  std::vector<glm::u8vec4> colors_;
};

struct InteractionSceneOptions {
  bool creasePatternPanel = false;
  bool handMarkers = false;  // both hands as markers (replays); the desktop's mouse needs none
  CreasePatternCache* panelCache = nullptr;  // null: the panel is built from the shown sheet
  // The studio's target shape (issue 27; sheet coordinates), drawn as a translucent ghost.
  const TriangleMesh* target = nullptr;
  // The part the suggestion on offer (InteractionCore::offeredFold) moves, where it goes (sheet
  // coordinates), drawn translucent beside its grab and drop points; null: the points alone.
  const TriangleMesh* offeredResult = nullptr;
};

// Both controllers as simple generic models (no vendor meshes), for the headset: the sheet hand
// a grip body at its grip pose, the point hand a body behind its aim pose with a pointer to the
// tip and the tip itself as a small sphere (when its aim pose is known; else a sphere at the tip).
// Bodies are lines; a squeeze lights the body that squeezes.
void addControllerModels(Scene& scene, const InteractionCore& core, const InputFrame& input,
                         const std::optional<Pose>& pointAim);

// A tracked bare hand (issue 16) as its 26 joints (small spheres) and bones (lines), in `color`.
void addHandModel(Scene& scene, const HandJoints& hand, const glm::vec4& color);
// The pinch point and its state: white while the tips are apart, warming to yellow as they close,
// green and larger while pinched (`openness`: HandInput::pinchOpenness).
void addPinchPoint(Scene& scene, const glm::dvec3& point, bool pinched, double openness);

Scene sceneForInteraction(const InteractionCore& core, const InputFrame& input,
                          const Camera& camera, const Ground& ground,
                          const InteractionSceneOptions& options = {});

}  // namespace curvefold::desktop
