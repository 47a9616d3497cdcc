// Left or right: a hand, or the dominant one (a handedness). One enum for every layer, its values
// indexing both hands' arrays in OpenXR's order (XR_HAND_LEFT_EXT, XR_HAND_RIGHT_EXT; the
// /user/hand/left and /user/hand/right subaction paths).
#pragma once

#include <string_view>

namespace curvefold {

enum class HandSide { Left = 0, Right = 1 };

constexpr HandSide otherHand(HandSide side) {
  return side == HandSide::Left ? HandSide::Right : HandSide::Left;
}

// "left" or "right", as OpenXR's paths and the recordings spell it.
constexpr std::string_view handSideName(HandSide side) {
  return side == HandSide::Left ? "left" : "right";
}

}  // namespace curvefold
