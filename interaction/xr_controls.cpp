#include "interaction/xr_controls.hpp"

#include <array>

namespace curvefold {

namespace {

using C = XrControl;

// Poses and haptics on both hands; clutch and select on both (read from the hand in the role).
#define CURVEFOLD_BOTH(control, input)                         \
  XrControlBinding{control, "left", input}, XrControlBinding { \
    control, "right", input                                    \
  }

constexpr std::array kSimple{
    CURVEFOLD_BOTH(C::GripPose, "/input/grip/pose"),
    CURVEFOLD_BOTH(C::AimPose, "/input/aim/pose"),
    // One button each: select clutches on the sheet hand and grabs on the point hand; menu undoes
    // on the sheet hand and cancels on the point hand. No redo or switch.
    CURVEFOLD_BOTH(C::Clutch, "/input/select/click"),
    CURVEFOLD_BOTH(C::Select, "/input/select/click"),
    CURVEFOLD_BOTH(C::Undo, "/input/menu/click"),
    CURVEFOLD_BOTH(C::Cancel, "/input/menu/click"),
    CURVEFOLD_BOTH(C::Haptic, "/output/haptic"),
};

constexpr std::array kOculusTouch{
    CURVEFOLD_BOTH(C::GripPose, "/input/grip/pose"),
    CURVEFOLD_BOTH(C::AimPose, "/input/aim/pose"),
    CURVEFOLD_BOTH(C::Clutch, "/input/squeeze/value"),
    CURVEFOLD_BOTH(C::Select, "/input/trigger/value"),
    XrControlBinding{C::Undo, "left", "/input/x/click"},
    XrControlBinding{C::Undo, "right", "/input/a/click"},
    XrControlBinding{C::Redo, "left", "/input/y/click"},
    XrControlBinding{C::Redo, "right", "/input/b/click"},
    CURVEFOLD_BOTH(C::Cancel, "/input/thumbstick/click"),
    XrControlBinding{C::SwitchHands, "left", "/input/menu/click"},  // the right has no menu
    CURVEFOLD_BOTH(C::Panel, "/input/thumbstick/click"),  // the sheet hand's; cancel the point's
    CURVEFOLD_BOTH(C::Scroll, "/input/thumbstick/y"),
    CURVEFOLD_BOTH(C::Haptic, "/output/haptic"),
};

constexpr std::array kValveIndex{
    CURVEFOLD_BOTH(C::GripPose, "/input/grip/pose"),
    CURVEFOLD_BOTH(C::AimPose, "/input/aim/pose"),
    CURVEFOLD_BOTH(C::Clutch, "/input/squeeze/value"),
    CURVEFOLD_BOTH(C::Select, "/input/trigger/value"),
    CURVEFOLD_BOTH(C::Undo, "/input/a/click"),
    CURVEFOLD_BOTH(C::Redo, "/input/b/click"),
    CURVEFOLD_BOTH(C::Cancel, "/input/thumbstick/click"),
    CURVEFOLD_BOTH(C::SwitchHands, "/input/trackpad/force"),
    CURVEFOLD_BOTH(C::Panel, "/input/thumbstick/click"),
    CURVEFOLD_BOTH(C::Scroll, "/input/thumbstick/y"),
    CURVEFOLD_BOTH(C::Haptic, "/output/haptic"),
};

constexpr std::array kHtcVive{
    CURVEFOLD_BOTH(C::GripPose, "/input/grip/pose"),
    CURVEFOLD_BOTH(C::AimPose, "/input/aim/pose"),
    CURVEFOLD_BOTH(C::Clutch, "/input/squeeze/click"),
    CURVEFOLD_BOTH(C::Select, "/input/trigger/value"),
    CURVEFOLD_BOTH(C::Undo, "/input/menu/click"),
    CURVEFOLD_BOTH(C::Cancel, "/input/menu/click"),
    CURVEFOLD_BOTH(C::Redo, "/input/trackpad/click"),
    CURVEFOLD_BOTH(C::Panel, "/input/trigger/click"),  // the sheet hand's trigger is free
    CURVEFOLD_BOTH(C::Scroll, "/input/trackpad/y"),
    CURVEFOLD_BOTH(C::Haptic, "/output/haptic"),
};

constexpr std::array kMicrosoftMotion{
    CURVEFOLD_BOTH(C::GripPose, "/input/grip/pose"),
    CURVEFOLD_BOTH(C::AimPose, "/input/aim/pose"),
    CURVEFOLD_BOTH(C::Clutch, "/input/squeeze/click"),
    CURVEFOLD_BOTH(C::Select, "/input/trigger/value"),
    CURVEFOLD_BOTH(C::Undo, "/input/menu/click"),
    CURVEFOLD_BOTH(C::Cancel, "/input/menu/click"),
    CURVEFOLD_BOTH(C::Redo, "/input/trackpad/click"),
    CURVEFOLD_BOTH(C::SwitchHands, "/input/thumbstick/click"),
    CURVEFOLD_BOTH(C::Panel, "/input/trigger/value"),  // the sheet hand's trigger is free
    CURVEFOLD_BOTH(C::Scroll, "/input/thumbstick/y"),
    CURVEFOLD_BOTH(C::Haptic, "/output/haptic"),
};

#undef CURVEFOLD_BOTH

const std::array kProfiles{
    XrProfileControls{"/interaction_profiles/khr/simple_controller", kSimple},
    XrProfileControls{"/interaction_profiles/oculus/touch_controller", kOculusTouch},
    XrProfileControls{"/interaction_profiles/valve/index_controller", kValveIndex},
    XrProfileControls{"/interaction_profiles/htc/vive_controller", kHtcVive},
    XrProfileControls{"/interaction_profiles/microsoft/motion_controller", kMicrosoftMotion},
};

}  // namespace

XrControlRole roleOf(XrControl control) {
  switch (control) {
    case C::Clutch:
    case C::Undo:
    case C::Redo:
    case C::Panel:
      return XrControlRole::Sheet;
    case C::Select:
    case C::Cancel:
    case C::Scroll:
      return XrControlRole::Point;
    case C::SwitchHands:
      return XrControlRole::Either;
    case C::GripPose:
    case C::AimPose:
    case C::Haptic:
      break;
  }
  return XrControlRole::Both;
}

std::span<const XrProfileControls> xrProfileControls() {
  return kProfiles;
}

}  // namespace curvefold
