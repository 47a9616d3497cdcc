// The headset panel's place and the point hand's ray on it (issue 14): the panel is a rectangle
// held by the non-dominant hand, and the dominant hand's aim ray (InputFrame::PointHand::aim)
// works it as a mouse works a window, the trigger as its button. No ImGui here: this decides where
// the ray is and whom the point hand serves; the app's panel turns that into clicks.
#pragma once

#include <optional>

#include <glm/vec2.hpp>

#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"

namespace curvefold {

// The panel in the sheet hand's frame: its centre and axes (x right, y up, the face towards +Z),
// and its size in metres.
struct PanelPlacement {
  Pose handFromPanel;
  glm::dvec2 size{0.24, 0.30};
};

// Above the non-dominant hand, facing where the hand's +Z faces (the user, for a hand held out
// in front), clear of the crease-pattern card beside the hand.
PanelPlacement heldPanelPlacement();

// Where a ray meets the panel's plane, from the front: uv from the top-left corner (0, 0) to the
// bottom-right (1, 1), outside [0, 1] off the panel.
struct PanelRayHit {
  glm::dvec2 uv{0.0};
  double distance = 0.0;  // along the ray, metres
  bool onPanel() const { return uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0; }
};

// None when the ray is parallel to the panel, comes from behind it, points away from it, or
// meets it further than maxDistance.
std::optional<PanelRayHit> rayOnPanel(const Pose& worldFromPanel, const glm::dvec2& size,
                                      const glm::dvec3& origin, const glm::dvec3& direction,
                                      double maxDistance = 3.0);

// Who the point hand serves, decided once a frame. The panel has it while the ray is on the panel
// and no drag is under way, and keeps it from a press on the panel until the trigger is released
// (a slider dragged past the panel's edge keeps sliding; a press that began on the panel never
// grabs the sheet). The panel's button is down only for presses that began on it.
class PanelPointer {
 public:
  explicit PanelPointer(const InteractionThresholds& thresholds = {}) : thresholds_(thresholds) {}

  // hit: the ray on the panel's plane (none without an aim, a shown panel or a hit).
  PointTarget update(const InputFrame& frame, const std::optional<PanelRayHit>& hit, bool dragging);
  // The panel's (mouse) button: the trigger, held since a press on the panel.
  bool buttonDown() const { return selectHeld_ && pressOnPanel_; }
  PointTarget target() const { return target_; }
  // Forgets the trigger (the panel was hidden or the hands switched).
  void reset();

 private:
  InteractionThresholds thresholds_;
  bool selectHeld_ = false;
  bool pressOnPanel_ = false;
  PointTarget target_ = PointTarget::Sheet;
};

}  // namespace curvefold
