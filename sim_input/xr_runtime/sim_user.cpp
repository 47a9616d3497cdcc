#include "sim_input/xr_runtime/sim_user.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/text/decimal.hpp"
#include "engine/text/excerpt.hpp"
#include "interaction/xr_controls.hpp"
#include "sim_input/gestures.hpp"
#include "sim_input/simulated_hand.hpp"

namespace curvefold::simxr {

namespace {

std::string env(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

}  // namespace

SimConfig SimConfig::fromEnvironment() {
  SimConfig config;
  const std::string input = env("CURVEFOLD_SIM_INPUT");
  if (!input.empty()) {
    if (input.ends_with(".gesture.json"))
      config.input = recordGestureScript(input);
    else
      config.input = readRecording(input, {.allowTruncated = true});
  }
  config.forcedProfile = env("CURVEFOLD_SIM_PROFILE");
  config.saveViews = env("CURVEFOLD_SIM_SAVE_VIEWS");
  if (!config.saveViews.empty()) {
    // The folder is made as a camera's would be: the views are what was asked for.
    std::error_code error;
    std::filesystem::create_directories(config.saveViews, error);
    if (error)
      throw std::runtime_error("CURVEFOLD_SIM_SAVE_VIEWS: cannot create " + config.saveViews +
                               ": " + error.message());
  }
  config.logPath = env("CURVEFOLD_SIM_LOG");
  config.hold = env("CURVEFOLD_SIM_HOLD") == "1";
  config.realtime = env("CURVEFOLD_SIM_REALTIME") == "1";
  config.noHmd = env("CURVEFOLD_SIM_NO_HMD") == "1";
  config.hands = env("CURVEFOLD_SIM_HANDS") == "1";
  if (const std::string jitter = env("CURVEFOLD_SIM_JITTER"); !jitter.empty()) {
    double mm = -1.0;
    if (!readDecimal(jitter, mm) || !(mm >= 0.0 && mm <= 50.0))
      throw std::runtime_error("CURVEFOLD_SIM_JITTER: expected millimetres from 0 to 50, got " +
                               quotedExcerpt(jitter));
    config.jitter = mm * 1e-3;
  }
  if (const std::string seed = env("CURVEFOLD_SIM_SEED"); !seed.empty()) {
    std::uint64_t value = 0;
    if (!readDecimal(seed, value))
      throw std::runtime_error(
          "CURVEFOLD_SIM_SEED: expected a whole number from 0 to 2^64 - 1, got " +
          quotedExcerpt(seed));
    config.seed = value;
  }
  if (const std::string size = env("CURVEFOLD_SIM_VIEW_SIZE"); !size.empty()) {
    unsigned w = 0, h = 0;
    if (!readSize(size, 16u, 4096u, w, h))
      throw std::runtime_error("CURVEFOLD_SIM_VIEW_SIZE: expected WxH from 16 to 4096, got " +
                               quotedExcerpt(size));
    config.viewWidth = w;
    config.viewHeight = h;
  }
  std::stringstream events(env("CURVEFOLD_SIM_EVENTS"));
  for (std::string item; std::getline(events, item, ',');) {
    const auto colon = item.find(':');
    std::size_t frame = 0;
    if (colon == std::string::npos || !readDecimal(item.substr(0, colon), frame))
      throw std::runtime_error("CURVEFOLD_SIM_EVENTS: expected FRAME:EVENT, got " +
                               quotedExcerpt(item));
    const std::string event = item.substr(colon + 1);
    if (event != "loss_pending" && event != "instance_loss" && event != "exit" &&
        event != "hands" && event != "controllers" &&
        !event.starts_with("profile=/interaction_profiles/"))
      throw std::runtime_error("CURVEFOLD_SIM_EVENTS: unknown event " + quotedExcerpt(event));
    config.events[frame].push_back(event);
  }
  return config;
}

std::array<HandState, 2> SimUser::controllersFor(const InputFrame& frame,
                                                 std::string_view profile) {
  const HandSide sheet = otherHand(handedness_), point = handedness_;
  std::array<HandState, 2> hands;
  auto hand = [&](HandSide side) -> HandState& { return hands[std::size_t(side)]; };
  hand(sheet).tracked = frame.sheetHand.tracked;
  hand(sheet).pose = frame.sheetHand.pose;
  hand(point).tracked = frame.pointHand.tracked;
  // The recorded aim, or straight ahead (-Z); the tip kXrTipOffset ahead of the aim pose is the
  // recorded point.
  const glm::dquat aim = frame.pointHand.aim.value_or(glm::dquat(1.0, 0.0, 0.0, 0.0));
  hand(point).pose = {frame.pointHand.position + aim * glm::dvec3(0.0, 0.0, kXrTipOffset), aim};

  const XrProfileControls* controls = nullptr;
  for (const XrProfileControls& p : xrProfileControls())
    if (p.profile == profile) controls = &p;
  if (controls) {
    auto press = [&](XrControl control, HandSide side, double value) {
      bool pressed = false;
      for (const XrControlBinding& binding : controls->bindings)
        if (binding.control == control && binding.hand == handSideName(side)) {
          // A click is all or nothing.
          const float v = binding.input.ends_with("/click") ? (value >= 0.5 ? 1.0f : 0.0f)
                                                            : static_cast<float>(value);
          float& slot = hand(side).inputs[std::string(binding.input)];
          slot = std::max(slot, v);
          pressed = true;
        }
      return pressed;
    };
    press(XrControl::Clutch, sheet, frame.sheetHand.clutch);
    press(XrControl::Select, point, frame.pointHand.select);
    press(XrControl::Clutch, point, frame.pointHand.grip);  // both hands on the sheet
    press(XrControl::Cancel, point, frame.held(Button::Cancel) ? 1.0 : 0.0);
    press(XrControl::Undo, sheet, frame.held(Button::Undo) ? 1.0 : 0.0);
    press(XrControl::Redo, sheet, frame.held(Button::Redo) ? 1.0 : 0.0);
    press(XrControl::Panel, sheet, frame.held(Button::Panel) ? 1.0 : 0.0);
    // An axis is set, not raised: it may be negative.
    for (const XrControlBinding& binding : controls->bindings)
      if (binding.control == XrControl::Scroll && binding.hand == handSideName(point))
        hand(point).inputs[std::string(binding.input)] = static_cast<float>(frame.pointHand.scroll);
    const double switching = frame.held(Button::SwitchHands) ? 1.0 : 0.0;
    if (!press(XrControl::SwitchHands, point, switching))
      press(XrControl::SwitchHands, sheet, switching);
  }
  afterFrame(frame);
  return hands;
}

std::array<HandJoints, 2> SimUser::handsFor(const InputFrame& frame) {
  const HandSide sheet = otherHand(handedness_), point = handedness_;
  std::array<HandJoints, 2> hands;
  if (frame.sheetHand.tracked)
    hands[std::size_t(sheet)] = simulatedHand(frame.sheetHand.pose, sheet, sheetHandPosture(frame));
  if (frame.pointHand.tracked)
    hands[std::size_t(point)] = simulatedPointingHand(
        frame.pointHand.position, frame.pointHand.aim.value_or(glm::dquat(1.0, 0.0, 0.0, 0.0)),
        point, pointHandPosture(frame));
  afterFrame(frame);
  return hands;
}

void SimUser::afterFrame(const InputFrame& frame) {
  const auto switchBit = static_cast<std::uint32_t>(Button::SwitchHands);
  if ((frame.buttons & switchBit) && !(lastButtons_ & switchBit))
    handedness_ = otherHand(handedness_);
  lastButtons_ = frame.buttons;
}

Pose headPoseFor(const Pose& sheetFrame) {
  const glm::dvec3 head = sheetFrame.position + glm::dvec3(0.0, 0.2, 0.35);
  // lookAt gives view_from_world; the head's pose is its inverse.
  const glm::dmat4 view = glm::lookAtRH(head, sheetFrame.position, glm::dvec3(0.0, 1.0, 0.0));
  const glm::dquat orientation = glm::normalize(glm::conjugate(glm::quat_cast(glm::dmat3(view))));
  return {head, orientation};
}

}  // namespace curvefold::simxr
