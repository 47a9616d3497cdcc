#include "interaction/panel_pointer.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace curvefold {

PanelPlacement heldPanelPlacement() {
  PanelPlacement placement;
  // Its lower edge 15 cm above the hand, over the crease-pattern card beside the hand (which
  // reaches about 13 cm up), so neither covers the other.
  placement.handFromPanel.position = {0.0, 0.15 + 0.5 * placement.size.y, 0.0};
  return placement;
}

std::optional<PanelRayHit> rayOnPanel(const Pose& worldFromPanel, const glm::dvec2& size,
                                      const glm::dvec3& origin, const glm::dvec3& direction,
                                      double maxDistance) {
  const Pose panelFromWorld = worldFromPanel.inverse();
  const glm::dvec3 o = panelFromWorld.apply(origin);
  const glm::dvec3 d = panelFromWorld.applyToDirection(direction);
  // From the front (+Z side), towards the face.
  if (!(o.z > 0.0) || !(d.z < 0.0)) return std::nullopt;
  const double t = -o.z / d.z;
  const double length = glm::length(d);
  if (!std::isfinite(t) || !(length > 0.0) || t * length > maxDistance) return std::nullopt;
  const glm::dvec3 p = o + t * d;
  PanelRayHit hit;
  hit.uv = {p.x / size.x + 0.5, 0.5 - p.y / size.y};
  hit.distance = t * length;
  return hit;
}

void PanelPointer::reset() {
  selectHeld_ = false;
  pressOnPanel_ = false;
  target_ = PointTarget::Sheet;
}

PointTarget PanelPointer::update(const InputFrame& frame, const std::optional<PanelRayHit>& hit,
                                 bool dragging) {
  const InputFrame::PointHand& hand = frame.pointHand;
  const bool onPanel = hand.tracked && hit && hit->onPanel();
  const bool wasHeld = selectHeld_;
  if (hand.tracked) {
    if (selectHeld_ && hand.select <= thresholds_.selectRelease) selectHeld_ = false;
    if (!selectHeld_ && hand.select >= thresholds_.selectPress) selectHeld_ = true;
  }
  if (selectHeld_ && !wasHeld) pressOnPanel_ = onPanel && !dragging;
  if (!selectHeld_) pressOnPanel_ = false;
  if (dragging)
    target_ = PointTarget::Sheet;
  else if (pressOnPanel_ || onPanel)
    target_ = PointTarget::Panel;
  else
    target_ = PointTarget::Sheet;
  return target_;
}

}  // namespace curvefold
