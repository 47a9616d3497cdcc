// Hands for the simulated runtime and the tests (issue 16, docs/design.md 6): the 26 joints of
// XR_EXT_hand_tracking for an adult hand (a 19 cm hand, palm 9 cm long) in the few postures the
// interaction reads (open, pinching, closed, a thumb tap), placed by the palm or by the pinch
// point, and seeded jitter on every joint. The postures that make an input frame's state through
// HandInput are here too, so the simulated user and the app agree on one gesture table.
#pragma once

#include <optional>
#include <random>

#include "interaction/hand_input.hpp"
#include "interaction/hand_side.hpp"

namespace curvefold {

enum class HandShape { Open, Pinch, Closed };

struct HandPosture {
  HandShape shape = HandShape::Open;
  std::optional<HandJoint> tap;  // a fingertip the thumb touches (an open hand only)
};

// A hand whose palm joint is at `palm` (its -Z towards the fingers, +Y out of the back).
HandJoints simulatedHand(const Pose& palm, HandSide side, const HandPosture& posture);
// A hand placed so that its pinch point (between the thumb and index tips) is `pinchPoint` and
// it points (wrist over the middle knuckle) along `aim`'s -Z, the back of the hand towards +Y.
HandJoints simulatedPointingHand(const glm::dvec3& pinchPoint, const glm::dquat& aim, HandSide side,
                                 const HandPosture& posture);
// Moves every joint by a random offset of up to `radius` metres (uniform in the ball).
void jitterJoints(HandJoints& hand, double radius, std::mt19937_64& random);

// The postures that give a frame's sheet hand (clutch, taps for its buttons) and point hand
// (select, grip, taps) through HandInput.
HandPosture sheetHandPosture(const InputFrame& frame);
HandPosture pointHandPosture(const InputFrame& frame);

}  // namespace curvefold
