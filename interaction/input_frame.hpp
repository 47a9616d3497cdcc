// The one input type every source produces (OpenXR controllers, the desktop mouse, a recording, a
// gesture script): a snapshot of both hands in their roles (docs/design.md 5). No OpenXR or GLFW
// types, so the interaction core, the recorder and the player are shared by all sources.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace curvefold {

// A rigid transform: rotate by orientation (unit quaternion), then translate by position.
struct Pose {
  glm::dvec3 position{0.0};
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z

  glm::dvec3 apply(const glm::dvec3& p) const { return position + orientation * p; }
  glm::dvec3 applyToDirection(const glm::dvec3& d) const { return orientation * d; }
  Pose inverse() const {
    const glm::dquat inverted = glm::conjugate(orientation);
    return {inverted * -position, inverted};
  }
  // (this * other).apply(p) == this->apply(other.apply(p))
  Pose operator*(const Pose& other) const {
    return {apply(other.position), orientation * other.orientation};
  }
  bool operator==(const Pose&) const = default;
};

// Where a sheet starts in a room-scale (stage) space, metres: level, 1.1 m up (a table's height
// for a standing user), 45 cm ahead of the origin along -Z. Gesture scripts and `curvefold xr`
// start there, so a script's recording drives the XR app over the same sheet.
inline Pose defaultSheetFrame() {
  return {{0.0, 1.1, -0.45}, glm::dquat(1.0, 0.0, 0.0, 0.0)};
}

// Buttons as a bit mask of what is held this frame; the core reacts to presses (rising edges).
enum class Button : std::uint32_t {
  Cancel = 1u << 0,
  Undo = 1u << 1,
  Redo = 1u << 2,
  SwitchHands = 1u << 3,
  Panel = 1u << 4,  // shows or hides the headset's panel
  // The studio's suggested fold (issue 27): make the one on offer; offer the next one.
  TakeSuggestion = 1u << 5,
  NextSuggestion = 1u << 6,
};

// A fold the studio suggests (docs/design.md 9): the sheet point whose development point is `seed`
// (now at `grab`, sheet coordinates) dropped at `to` (sheet coordinates).
struct SuggestedFold {
  glm::dvec2 seed{0.0};
  glm::dvec3 grab{0.0};
  glm::dvec3 to{0.0};
  bool operator==(const SuggestedFold&) const = default;
};

// The live simulation (issue 39, 4): while a frame carries one, the sheet is drawn as the
// bar-and-hinge model folds it (interaction/live_simulation.hpp) instead of as designed, and the
// point hand pulls the sheet instead of folding it. Input like the hands, so a recording keeps it
// and a replay steps the very same way (a fixed step count per frame, never the wall clock).
struct SimulationPull {
  std::uint32_t vertex = 0;  // of the committed design's sheet
  glm::dvec3 to{0.0};        // where the spring pulls it, sheet coordinates
  bool operator==(const SimulationPull&) const = default;
};

// Which solver steps the live simulation: the CPU's dynamic solver (double, bit for bit on any
// machine) or the Vulkan compute one (float, bit for bit on one device only, so a recording of a
// GPU run is not replayed: sim_input/recording.hpp).
enum class LiveSolverKind : std::uint8_t { Cpu, Gpu };

struct SimulationInput {
  double percent = 0.0;     // fold amount, 0 (flat) to 100 (the design)
  std::uint32_t steps = 0;  // dynamic steps this frame
  std::optional<SimulationPull> pull;
  LiveSolverKind solver = LiveSolverKind::Cpu;
  bool operator==(const SimulationInput&) const = default;
};

struct InputFrame {
  double time = 0.0;  // seconds since the start of the session

  // Non-dominant hand: its 6-DOF pose holds the sheet while the clutch (grip) is squeezed.
  struct SheetHand {
    Pose pose;
    bool tracked = false;
    double clutch = 0.0;  // grip, 0 (open) to 1 (squeezed)
  } sheetHand;

  // Dominant hand: a 3-DOF point (the controller tip) that grabs with select (the trigger).
  struct PointHand {
    glm::dvec3 position{0.0};
    bool tracked = false;
    double select = 0.0;  // trigger, 0 (released) to 1 (pulled)
    // Squeeze, 0 to 1: with the sheet hand's clutch (and the trigger released) both hands hold
    // the sheet, which moves, turns and scales between them.
    double grip = 0.0;
    // Where the hand points (a headset's aim pose): the ray from `position` along this
    // orientation's -Z reaches the panel. None from sources without one (the mouse).
    std::optional<glm::dquat> aim;
    // Thumbstick or trackpad, -1 (down) to 1 (up): scrolls the panel under the ray.
    double scroll = 0.0;

    // The aim ray's direction (world).
    glm::dvec3 aimDirection() const {
      return aim ? *aim * glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0);
    }
  } pointHand;

  std::uint32_t buttons = 0;  // Button bits held

  // The studio's suggestions that arrived in this frame, best first (most frames have none). They
  // are input like the hands: the core offers them until the design changes, and a recording
  // keeps them, so a replay offers the same folds at the same moment without searching again.
  std::vector<SuggestedFold> suggestions;

  // Present while the sheet is simulated (see SimulationInput).
  std::optional<SimulationInput> simulation;

  bool held(Button button) const { return (buttons & static_cast<std::uint32_t>(button)) != 0; }
};

}  // namespace curvefold
