// Which controller input does what in curvefold's OpenXR interface (docs/design.md 5), as plain
// data with no OpenXR types: the XR input source suggests exactly these bindings, and the simulated
// runtime (sim_input/openxr_runtime) plays a user who presses exactly these controls, so a
// recording drives the app through the real action system.
//
// Roles: the clutch, undo and redo belong to the non-dominant (sheet) hand, as in Open Brush;
// select and cancel to the dominant (point) hand; switching hands is read from either hand. Each
// role-bound control is suggested on both physical hands, and the app reads it from the hand that
// has the role now, so switching hands needs no new bindings.
#pragma once

#include <span>
#include <string_view>

namespace curvefold {

enum class XrControl {
  GripPose,     // pose: the sheet hand's 6-DOF frame
  AimPose,      // pose: the point hand's tip is kXrTipOffset ahead of it
  Clutch,       // float: squeeze holds the sheet
  Select,       // float: trigger grabs and drags
  Cancel,       // boolean
  Undo,         // boolean
  Redo,         // boolean
  SwitchHands,  // boolean
  Panel,        // boolean: shows or hides the panel (the sheet hand's)
  Scroll,       // float -1..1: scrolls the panel (the point hand's thumbstick or trackpad)
  Haptic,       // vibration output
};

// The hand whose role a control belongs to.
enum class XrControlRole { Sheet, Point, Either, Both };
XrControlRole roleOf(XrControl control);

// The dominant hand's 3-DOF point: this far (metres) ahead of its aim pose, along the aim pose's
// -Z (the pointing direction), about where a controller's tip ends.
inline constexpr double kXrTipOffset = 0.05;

struct XrControlBinding {
  XrControl control;
  std::string_view hand;   // "left" or "right"
  std::string_view input;  // under /user/hand/<hand>, e.g. "/input/squeeze/value"
};

struct XrProfileControls {
  std::string_view profile;  // e.g. "/interaction_profiles/oculus/touch_controller"
  std::span<const XrControlBinding> bindings;
};

// The profiles curvefold suggests bindings for: khr/simple_controller, oculus/touch_controller,
// valve/index_controller, htc/vive_controller, microsoft/motion_controller.
std::span<const XrProfileControls> xrProfileControls();

// "/user/hand/left" + input, for path strings.
inline constexpr std::string_view kXrLeftHand = "/user/hand/left";
inline constexpr std::string_view kXrRightHand = "/user/hand/right";

}  // namespace curvefold
