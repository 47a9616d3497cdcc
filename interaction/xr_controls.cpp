#include "interaction/xr_controls.hpp"

#include <array>

namespace curvefold {

namespace {

using C = XrControl;

// A control's input on both hands, or on one ("left" or "right") where the hands differ.
struct Input {
  XrControl control;
  std::string_view path;
  std::string_view hand = {};
};

// A profile's bindings: its inputs between the poses and the haptic, which every profile has on
// both hands.
template <const auto& kInputs>
constexpr auto withPosesAndHaptic() {
  constexpr std::size_t count = [] {
    std::size_t n = 3 * 2;
    for (const Input& input : kInputs) n += input.hand.empty() ? 2 : 1;
    return n;
  }();
  std::array<XrControlBinding, count> bindings{};
  std::size_t next = 0;
  const auto add = [&](const Input& input) {
    for (std::string_view hand : {"left", "right"})
      if (input.hand.empty() || input.hand == hand)
        bindings[next++] = {input.control, hand, input.path};
  };
  add({C::GripPose, "/input/grip/pose"});
  add({C::AimPose, "/input/aim/pose"});
  for (const Input& input : kInputs) add(input);
  add({C::Haptic, "/output/haptic"});
  return bindings;
}

// One button each: select clutches on the sheet hand and grabs on the point hand; menu undoes on
// the sheet hand and cancels on the point hand. No redo or switch.
constexpr Input kSimpleInputs[]{
    {C::Clutch, "/input/select/click"},
    {C::Select, "/input/select/click"},
    {C::Undo, "/input/menu/click"},
    {C::Cancel, "/input/menu/click"},
};

constexpr Input kOculusTouchInputs[]{
    {C::Clutch, "/input/squeeze/value"},
    {C::Select, "/input/trigger/value"},
    {C::Undo, "/input/x/click", "left"},
    {C::Undo, "/input/a/click", "right"},
    {C::Redo, "/input/y/click", "left"},
    {C::Redo, "/input/b/click", "right"},
    {C::Cancel, "/input/thumbstick/click"},
    {C::SwitchHands, "/input/menu/click", "left"},  // the right has no menu
    {C::Panel, "/input/thumbstick/click"},          // the sheet hand's; cancel the point's
    {C::Scroll, "/input/thumbstick/y"},
};

constexpr Input kValveIndexInputs[]{
    {C::Clutch, "/input/squeeze/value"},
    {C::Select, "/input/trigger/value"},
    {C::Undo, "/input/a/click"},
    {C::Redo, "/input/b/click"},
    {C::Cancel, "/input/thumbstick/click"},
    {C::SwitchHands, "/input/trackpad/force"},
    {C::Panel, "/input/thumbstick/click"},
    {C::Scroll, "/input/thumbstick/y"},
};

constexpr Input kHtcViveInputs[]{
    {C::Clutch, "/input/squeeze/click"},
    {C::Select, "/input/trigger/value"},
    {C::Undo, "/input/menu/click"},
    {C::Cancel, "/input/menu/click"},
    {C::Redo, "/input/trackpad/click"},
    {C::Panel, "/input/trigger/click"},  // the sheet hand's trigger is free
    {C::Scroll, "/input/trackpad/y"},
};

constexpr Input kMicrosoftMotionInputs[]{
    {C::Clutch, "/input/squeeze/click"}, {C::Select, "/input/trigger/value"},
    {C::Undo, "/input/menu/click"},      {C::Cancel, "/input/menu/click"},
    {C::Redo, "/input/trackpad/click"},  {C::SwitchHands, "/input/thumbstick/click"},
    {C::Panel, "/input/trigger/value"},  // the sheet hand's trigger is free
    {C::Scroll, "/input/thumbstick/y"},
};

constexpr auto kSimple = withPosesAndHaptic<kSimpleInputs>();
constexpr auto kOculusTouch = withPosesAndHaptic<kOculusTouchInputs>();
constexpr auto kValveIndex = withPosesAndHaptic<kValveIndexInputs>();
constexpr auto kHtcVive = withPosesAndHaptic<kHtcViveInputs>();
constexpr auto kMicrosoftMotion = withPosesAndHaptic<kMicrosoftMotionInputs>();

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
