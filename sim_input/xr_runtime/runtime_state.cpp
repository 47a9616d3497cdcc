// The simulated OpenXR runtime (docs/design.md 6): a shared library the Khronos loader loads
// through XR_RUNTIME_JSON (the manifest is generated beside it). It serves a head and two
// controllers (or, with XR_EXT_hand_tracking, two bare hands) from a recording, frame-locked (one
// recorded frame per focused xrWaitFrame), runs the session state machine a real runtime runs,
// resolves actions through the application's suggested bindings for the current interaction
// profile, and makes XR_KHR_vulkan_enable2 swapchains on the application's device (XR_MND_headless
// sessions have none) in sRGB and UNORM colour formats and the device's depth formats, and takes
// depth images with XR_KHR_composition_layer_depth. Its log names each swapchain's format and, per
// frame, how many views came with depth. sim_user.hpp lists its settings.
//
// One instance at a time; every entry point validates its handles and structure types and
// catches exceptions at the C boundary.
//
// This file: the shared state and the helpers every part uses.
#include "sim_input/xr_runtime/runtime_state.hpp"

namespace curvefold::simxr {

Instance* gInstance = nullptr;
std::set<void*> gHandles;

[[noreturn]] void fail(XrResult result) {
  throw Failure{result};
}

Instance& instanceOf(XrInstance handle) {
  Instance* instance = objectOf<Instance>(handle);
  if (!instance || instance != gInstance) fail(XR_ERROR_HANDLE_INVALID);
  if (instance->lost) fail(XR_ERROR_INSTANCE_LOST);
  return *instance;
}

Session& sessionOf(XrSession handle) {
  Session* session = objectOf<Session>(handle);
  if (!session || !gInstance || !gInstance->sessions.count(session)) fail(XR_ERROR_HANDLE_INVALID);
  if (gInstance->lost) fail(XR_ERROR_INSTANCE_LOST);
  return *session;
}

Session& liveSessionOf(XrSession handle) {
  Session& session = sessionOf(handle);
  if (session.lost) fail(XR_ERROR_SESSION_LOST);
  return session;
}

void log(const std::string& line) {
  if (gInstance && gInstance->log.is_open()) gInstance->log << line << std::endl;
}

const std::string& pathString(Instance& instance, XrPath path) {
  if (path == XR_NULL_PATH || path >= instance.paths.size()) fail(XR_ERROR_PATH_INVALID);
  return instance.paths[path];
}

const char* stateName(XrSessionState state) {
  switch (state) {
#define CURVEFOLD_SIM_STATE(name, value) \
  case name:                             \
    return &#name[17];  // after "XR_SESSION_STATE_"
    XR_LIST_ENUM_XrSessionState(CURVEFOLD_SIM_STATE)
#undef CURVEFOLD_SIM_STATE
        default : return "?";
  }
}

void pushEvent(Instance& instance, const void* event, std::size_t size) {
  XrEventDataBuffer buffer{XR_TYPE_EVENT_DATA_BUFFER};
  std::memcpy(&buffer, event, size);
  instance.events.push_back(buffer);
}

void setState(Session& session, XrSessionState state) {
  session.state = state;
  XrEventDataSessionStateChanged event{XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED};
  event.session = reinterpret_cast<XrSession>(&session);
  event.state = state;
  event.time = gInstance->time;
  pushEvent(*gInstance, &event, sizeof event);
  log(std::string("state ") + stateName(state));
}

// Runtime-requested or app-requested end: down through the states to STOPPING.
void stop(Session& session) {
  if (!session.running || session.state == XR_SESSION_STATE_STOPPING) return;
  if (session.state == XR_SESSION_STATE_FOCUSED) setState(session, XR_SESSION_STATE_VISIBLE);
  if (session.state == XR_SESSION_STATE_VISIBLE) setState(session, XR_SESSION_STATE_SYNCHRONIZED);
  setState(session, XR_SESSION_STATE_STOPPING);
}

void profileChanged(Instance& instance, Session& session) {
  XrEventDataInteractionProfileChanged event{XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED};
  event.session = reinterpret_cast<XrSession>(&session);
  pushEvent(instance, &event, sizeof event);
  log("profile " + instance.profile);
}

std::string chosenProfile(const Instance& instance) {
  if (instance.servingHands) return "";  // the controllers are down
  if (!instance.config.forcedProfile.empty())
    return instance.bindings.count(instance.config.forcedProfile) ? instance.config.forcedProfile
                                                                  : "";
  for (const char* profile : kProfilePreference)
    if (instance.bindings.count(profile)) return profile;
  return "";
}

// The value of an action on a hand through the current profile's bindings.
std::optional<float> resolve(Instance& instance, const Action& action, int hand) {
  const auto found = instance.bindings.find(instance.profile);
  if (found == instance.bindings.end()) return std::nullopt;
  std::optional<float> value;
  for (const auto& [bound, path] : found->second) {
    if (bound != &action) continue;
    std::string component;
    if (handOf(path, &component) != hand) continue;
    const auto& inputs = instance.hands[hand].inputs;
    // Several sources of one action: the largest magnitude wins (an axis may be negative).
    auto larger = [](float a, float b) { return std::abs(b) > std::abs(a) ? b : a; };
    float v = 0.0f;
    for (const std::string& key :
         {component, component + "/value", component + "/click", component + "/force"})
      if (auto it = inputs.find(key); it != inputs.end()) v = larger(v, it->second);
    if (action.type == XR_ACTION_TYPE_BOOLEAN_INPUT) v = v >= 0.5f ? 1.0f : 0.0f;
    value = larger(value.value_or(0.0f), v);
  }
  return value;
}

int handIndex(Instance& instance, XrPath path) {
  if (path == XR_NULL_PATH) return -1;
  const int hand = handOf(pathString(instance, path));
  if (hand < 0) fail(XR_ERROR_PATH_UNSUPPORTED);
  return hand;
}

void serveFrame(Instance& instance, Session& session) {
  const SimConfig& config = instance.config;
  const XrDuration period =
      config.input ? XrDuration(1e9 / std::max(config.input->header.rate, 1.0)) : 11'111'111;
  if (!config.input || session.state != XR_SESSION_STATE_FOCUSED) {
    instance.time += period;
    return;
  }
  const auto& frames = config.input->frames;
  if (instance.nextFrame >= frames.size()) {
    instance.time += period;
    if (!config.hold) {
      session.exitRequested = true;
      stop(session);
    }
    return;
  }
  const std::size_t index = instance.nextFrame++;
  XrDuration step = period;
  if (instance.served)
    step = std::max<XrDuration>(
        1, XrDuration((frames[index].time - frames[*instance.served].time) * 1e9));
  instance.served = index;
  instance.time += step;
  log("frame " + std::to_string(index));
  if (auto events = config.events.find(index); events != config.events.end())
    for (const std::string& event : events->second) {
      log("event " + event);
      if (event == "hands" || event == "controllers") {
        // Controllers put down or picked up: the interaction profile goes or comes back.
        instance.servingHands = event == "hands";
        const std::string profile = chosenProfile(instance);
        if (profile != instance.profile) {
          instance.profile = profile;
          profileChanged(instance, session);
        }
      }
      if (event == "loss_pending") {
        // The session works until the application has seen the event, then it is lost.
        setState(session, XR_SESSION_STATE_LOSS_PENDING);
        instance.unavailableSystems = 2;
      } else if (event == "instance_loss") {
        XrEventDataInstanceLossPending loss{XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING};
        loss.lossTime = instance.time;
        pushEvent(instance, &loss, sizeof loss);
        instance.lossPending = true;
      } else if (event == "exit") {
        session.exitRequested = true;
        stop(session);
      } else if (event.starts_with("profile=")) {
        instance.profile = event.substr(8);
        profileChanged(instance, session);
      }
    }
  // The user's hands for the frame: holding controllers, or bare and tracked.
  if (instance.servingHands) {
    instance.hands = {};
    instance.handJoints = instance.user->handsFor(frames[index]);
    for (HandJoints& hand : instance.handJoints)
      if (hand.tracked) jitterJoints(hand, config.jitter, instance.random);
  } else {
    instance.handJoints = {};
    instance.hands = instance.user->controllersFor(frames[index], instance.profile);
  }
}

Pose locate(Instance& instance, const Space& space, bool& valid) {
  valid = true;
  if (space.action) {
    const int hand = space.subaction == XR_NULL_PATH ? 0 : handIndex(instance, space.subaction);
    valid = instance.hands[hand].tracked && resolve(instance, *space.action, hand).has_value() &&
            space.session->state == XR_SESSION_STATE_FOCUSED;
    return instance.hands[hand].pose * space.offset;
  }
  if (space.reference == XR_REFERENCE_SPACE_TYPE_VIEW) {
    const Pose sheet =
        instance.config.input ? instance.config.input->header.sheetFrame : defaultSheetFrame();
    return headPoseFor(sheet) * space.offset;
  }
  return space.offset;  // stage and local: the recording's world
}

XrPosef toXr(const Pose& pose) {
  XrPosef p;
  p.position = {float(pose.position.x), float(pose.position.y), float(pose.position.z)};
  p.orientation = {float(pose.orientation.x), float(pose.orientation.y), float(pose.orientation.z),
                   float(pose.orientation.w)};
  return p;
}

Pose fromXr(const XrPosef& p) {
  return {{p.position.x, p.position.y, p.position.z},
          glm::normalize(
              glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z))};
}

void saveViews(Session& session, Swapchain* only) {
  if (!gInstance || gInstance->config.saveViews.empty()) return;
  // Views may share an array swapchain (a layer each): every view is saved before any image is
  // marked as saved.
  std::vector<Swapchain*> saved;
  for (auto& [view, image] : session.lastViewSwapchain) {
    Swapchain* swapchain = image.swapchain;
    if (!swapchain || (only && swapchain != only) || swapchain->lastReleased < 0) continue;
    const std::string name = "view" + std::to_string(view) + ".png";
    swapchain->images->savePng(std::uint32_t(swapchain->lastReleased), image.layer,
                               std::filesystem::path(gInstance->config.saveViews) / name);
    log("saved " + name);
    saved.push_back(swapchain);
  }
  for (Swapchain* swapchain : saved) swapchain->lastReleased = -1;
}

void destroySwapchain(Swapchain* swapchain) {
  saveViews(*swapchain->session, swapchain);
  for (auto& [view, last] : swapchain->session->lastViewSwapchain)
    if (last.swapchain == swapchain) last.swapchain = nullptr;
  swapchain->session->swapchains.erase(swapchain);
  gHandles.erase(swapchain);
  delete swapchain;
}

void destroySession(Session* session) {
  // Its pending events die with it (a new session may get the same handle value).
  std::erase_if(gInstance->events, [&](const XrEventDataBuffer& event) {
    const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
    return (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED ||
            event.type == XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED) &&
           changed.session == reinterpret_cast<XrSession>(session);
  });
  for (Swapchain* swapchain : std::set<Swapchain*>(session->swapchains))
    destroySwapchain(swapchain);
  for (HandTracker* tracker : std::set<HandTracker*>(session->handTrackers))
    destroyHandTracker(tracker);
  for (Space* space : session->spaces) {
    gHandles.erase(space);
    delete space;
  }
  gInstance->sessions.erase(session);
  gHandles.erase(session);
  delete session;
}

}  // namespace curvefold::simxr
