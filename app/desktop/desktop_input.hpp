// The desktop source (docs/design.md 5, desktop fallback): mouse and keyboard become InputFrames
// for the same InteractionCore as VR, so a desktop session records and replays like any other.
//
// Mapping. The sheet hand is not used (untracked): the sheet keeps the recording's initial frame,
// and orbit/pan/zoom move only the camera, which is a view and never part of the input. The point
// hand is the mouse ray's hit on the displayed sheet (untracked when the ray misses), so the core's
// hover follows the mouse; a left press there pulls select, and the tip, lying exactly on the
// surface, is grabbed with no offset. While held the tip follows the mouse ray in the plane
// through it parallel to the screen (fixed at the press), and the wheel moves it (and that plane)
// along the view direction. Escape, Ctrl+Z and Ctrl+Shift+Z pulse the Cancel, Undo and Redo
// buttons for one frame. No GLFW types, so it is tested without a window.
#pragma once

#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/render/scene.hpp"
#include "engine/render/scene_builder.hpp"
#include "interaction/input_frame.hpp"

namespace curvefold::desktop {

struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};  // unit
};

// Nearest intersection of the ray with the sheet's triangles (placed by worldFromSheet), in world
// coordinates; nothing when it misses. Brute force over the triangles: one query per mouse move.
std::optional<glm::dvec3> intersectSheet(const Ray& ray, const Sheet& sheet,
                                         const Pose& worldFromSheet);

// A camera orbiting a target: yaw about world +y, pitch above the horizon, distance.
class OrbitCamera {
 public:
  // The front view (frameBounds with ViewPreset::Front) of the sheet: deterministic, so a test can
  // compute where a vertex appears.
  static OrbitCamera framing(const Sheet& sheet, const Pose& worldFromSheet, float aspect);
  // The front view of a world box (the sheet's and a target's together, issue 38, 4).
  static OrbitCamera framing(const Bounds& bounds, float aspect);

  Camera camera() const;
  glm::dvec3 eye() const;
  glm::dvec3 forward() const;  // unit, from the eye to the target
  // The ray through a pixel position (x right, y down, in window pixels of a width x height view).
  Ray ray(glm::dvec2 pixel, double width, double height) const;
  // Where a world point appears, in the same pixel coordinates.
  glm::dvec2 project(const glm::dvec3& p, double width, double height) const;
  // Whether the whole box (its eight corners) lies in front of the eye and inside the view.
  bool shows(const Bounds& bounds, double width, double height) const;

  void orbit(double dxPixels, double dyPixels);
  void pan(double dxPixels, double dyPixels, double height);
  void zoom(double wheelSteps);

  glm::dvec3 target{0.0};
  double yaw = 0.0;    // radians; 0 looks along -z (the eye on +z)
  double pitch = 0.0;  // radians
  double distance = 1.0;
  double fovYDegrees = 35.0;
};

// The world box of the sheet (placed by worldFromSheet) and, when there is one, of the target
// (sheet coordinates, placed the same way): what the designer's view frames.
Bounds studioBounds(const Sheet& sheet, const TriangleMesh* target, const Pose& worldFromSheet);

// After the committed sheet changed (issue 38, 4: a suggestion taken toward a target elsewhere):
// a view that showed the whole sheet before (sheetWasShown) and no longer shows `sheet` frames
// `framed` (the sheet with the target) again; any other view is the user's (zoomed in) and stays.
// Returns whether the camera moved.
bool followSheet(OrbitCamera& camera, bool sheetWasShown, const Bounds& sheet, const Bounds& framed,
                 double width, double height);

class DesktopInput {
 public:
  // How far one wheel step moves a grabbed point in depth, metres.
  explicit DesktopInput(double depthStep = 0.01) : depthStep_(depthStep) {}

  // The mouse ray moved (every frame is fine). `sheet` is what is displayed now.
  void mouseRay(const Ray& ray, const Sheet& sheet, const Pose& worldFromSheet);
  // Left button. A press on the sheet grabs (returns true); elsewhere it does nothing.
  bool press(const Ray& ray, const Sheet& sheet, const Pose& worldFromSheet,
             const glm::dvec3& viewForward);
  void release();
  // Wheel while dragging: moves the tip along the view direction (away for positive steps).
  void wheel(double steps);
  void pulse(Button button) { pulses_ |= static_cast<std::uint32_t>(button); }

  bool dragging() const { return dragging_; }
  // The frame for this moment; pulsed buttons are held in it and cleared afterwards.
  InputFrame frame(double time);

 private:
  double depthStep_;
  bool tracked_ = false;
  bool dragging_ = false;
  glm::dvec3 tip_{0.0};
  glm::dvec3 planeNormal_{0.0, 0.0, 1.0};
  std::uint32_t pulses_ = 0;
};

}  // namespace curvefold::desktop
