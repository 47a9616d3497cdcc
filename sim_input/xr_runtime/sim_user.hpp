// What the simulated runtime serves (configured by environment variables, since the loader, not
// the application, loads it) and the simulated user: controller states made from recorded input
// frames by pressing what the controls table (interaction/xr_controls.hpp) says, or bare hands in
// the postures that give the frame through the hand gesture table (interaction/hand_input.hpp).
//
//   CURVEFOLD_SIM_INPUT       a recording (*.jsonl) or gesture script (*.gesture.json) to serve
//   CURVEFOLD_SIM_PROFILE     the interaction profile to use (default: the first of oculus/touch,
//                             valve/index, htc/vive, microsoft/motion, khr/simple suggested)
//   CURVEFOLD_SIM_HANDS=1     serve tracked hands (XR_EXT_hand_tracking) and no controllers: the
//                             26 joints of each hand made from each frame (pinching while select
//                             is held, closed while the clutch is, taps for buttons:
//                             sim_input/simulated_hand.hpp)
//   CURVEFOLD_SIM_NO_HAND_TRACKING=1  a runtime without XR_EXT_hand_tracking
//   CURVEFOLD_SIM_JITTER      MM: every served hand joint moved by up to that many millimetres at
//                             random (seeded by CURVEFOLD_SIM_SEED, default 1, so runs repeat)
//   CURVEFOLD_SIM_EVENTS      FRAME:EVENT,... with EVENT loss_pending, instance_loss, exit,
//                             profile=/interaction_profiles/..., hands (the controllers put down:
//                             hands served from then on) or controllers (picked up again), when
//                             that frame is served
//   CURVEFOLD_SIM_HOLD=1      after the last frame, keep serving it instead of asking to exit
//   CURVEFOLD_SIM_REALTIME=1  xrWaitFrame keeps the recording's pace
//   CURVEFOLD_SIM_NO_HMD=1    no headset connected (xrGetSystem fails)
//   CURVEFOLD_SIM_VIEW_SIZE   WxH of each view (default 512x512)
//   CURVEFOLD_SIM_SAVE_VIEWS  a folder: each view's last image is written there as view<i>.png
//   CURVEFOLD_SIM_LOG         a file: one line per state change, served frame, profile, haptic,
//                             swapchain (its format) and ended frame (its views, and how many
//                             came with depth)
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interaction/hand_input.hpp"
#include "interaction/input_frame.hpp"
#include "interaction/interaction_core.hpp"
#include "sim_input/recording.hpp"

namespace curvefold::simxr {

struct SimConfig {
  std::optional<Recording> input;
  std::string forcedProfile, saveViews, logPath;
  std::map<std::size_t, std::vector<std::string>> events;  // by frame index
  bool hold = false, realtime = false, noHmd = false;
  bool hands = false;   // hands, not controllers, from the start
  double jitter = 0.0;  // metres
  std::uint64_t seed = 1;
  std::uint32_t viewWidth = 512, viewHeight = 512;

  // Throws std::runtime_error naming the variable and the problem.
  static SimConfig fromEnvironment();
};

struct HandState {
  bool tracked = false;
  Pose pose;                                         // grip and aim alike
  std::map<std::string, float, std::less<>> inputs;  // component ("/input/x/click") -> value
};

class SimUser {
 public:
  explicit SimUser(HandSide handedness) : handedness_(handedness) {}
  // Both controllers (0 left, 1 right) for a frame, pressing the controls of `profile`; then
  // switches hands when the frame newly presses SwitchHands, as the interaction core does.
  std::array<HandState, 2> controllersFor(const InputFrame& frame, std::string_view profile);
  // Both hands' joints (0 left, 1 right) for a frame, in the postures that give its state
  // (simulated_hand.hpp); switches hands as controllersFor does.
  std::array<HandJoints, 2> handsFor(const InputFrame& frame);
  HandSide handedness() const { return handedness_; }

 private:
  // Follows a newly pressed SwitchHands, as the interaction core does.
  void afterFrame(const InputFrame& frame);

  HandSide handedness_;
  std::uint32_t lastButtons_ = 0;
};

// The head: 0.2 m above and 0.35 m behind the sheet frame's position, looking at it (paper
// held at about 40 cm from the eyes).
Pose headPoseFor(const Pose& sheetFrame);
inline constexpr double kSimEyeSeparation = 0.063;

}  // namespace curvefold::simxr
