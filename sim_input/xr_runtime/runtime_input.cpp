// The simulated OpenXR runtime: spaces and actions (the specification's "Spaces" and "Input"
// chapters): reference and action spaces located from the served hands, action sets, suggested
// bindings checked per profile, syncing, action states and haptics.
#include "sim_input/xr_runtime/runtime_state.hpp"

namespace curvefold::simxr {

XRAPI_ATTR XrResult XRAPI_CALL enumerateReferenceSpaces(XrSession handle, std::uint32_t capacity,
                                                        std::uint32_t* count,
                                                        XrReferenceSpaceType* out) {
  return guard([&] {
    sessionOf(handle);
    fill(std::vector<XrReferenceSpaceType>{XR_REFERENCE_SPACE_TYPE_VIEW,
                                           XR_REFERENCE_SPACE_TYPE_LOCAL,
                                           XR_REFERENCE_SPACE_TYPE_STAGE},
         capacity, count, out);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createReferenceSpace(XrSession handle,
                                                    const XrReferenceSpaceCreateInfo* info,
                                                    XrSpace* out) {
  return guard([&] {
    Session& session = sessionOf(handle);
    checkType(info, XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    if (!out) return XR_ERROR_VALIDATION_FAILURE;
    if (info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_VIEW &&
        info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_LOCAL &&
        info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_STAGE)
      return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
    auto* space = new Space{&session, info->referenceSpaceType, nullptr, XR_NULL_PATH,
                            fromXr(info->poseInReferenceSpace)};
    session.spaces.insert(space);
    *out = handleOf<XrSpace>(space);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getReferenceSpaceBoundsRect(XrSession handle,
                                                           XrReferenceSpaceType type,
                                                           XrExtent2Df* bounds) {
  return guard([&] {
    sessionOf(handle);
    if (!bounds) return XR_ERROR_VALIDATION_FAILURE;
    if (type != XR_REFERENCE_SPACE_TYPE_STAGE) {
      *bounds = {0.0f, 0.0f};
      return XR_SPACE_BOUNDS_UNAVAILABLE;
    }
    *bounds = {3.0f, 3.0f};
    return XR_SUCCESS;
  });
}

Action& actionOf(XrAction handle) {
  Action* action = objectOf<Action>(handle);
  if (!action) fail(XR_ERROR_HANDLE_INVALID);
  return *action;
}

XRAPI_ATTR XrResult XRAPI_CALL createActionSpace(XrSession handle,
                                                 const XrActionSpaceCreateInfo* info,
                                                 XrSpace* out) {
  return guard([&] {
    Session& session = sessionOf(handle);
    checkType(info, XR_TYPE_ACTION_SPACE_CREATE_INFO);
    Action& action = actionOf(info->action);
    if (action.type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (info->subactionPath != XR_NULL_PATH &&
        std::find(action.subactions.begin(), action.subactions.end(), info->subactionPath) ==
            action.subactions.end())
      return XR_ERROR_PATH_UNSUPPORTED;
    auto* space = new Space{&session, XR_REFERENCE_SPACE_TYPE_STAGE, &action, info->subactionPath,
                            fromXr(info->poseInActionSpace)};
    session.spaces.insert(space);
    *out = handleOf<XrSpace>(space);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL locateSpace(XrSpace spaceHandle, XrSpace baseHandle, XrTime,
                                           XrSpaceLocation* location) {
  return guard([&] {
    Space* space = objectOf<Space>(spaceHandle);
    Space* base = objectOf<Space>(baseHandle);
    if (!space || !base) return XR_ERROR_HANDLE_INVALID;
    liveSessionOf(reinterpret_cast<XrSession>(space->session));
    checkType(location, XR_TYPE_SPACE_LOCATION);
    bool spaceValid = false, baseValid = false;
    const Pose world = locate(*gInstance, *space, spaceValid);
    const Pose worldBase = locate(*gInstance, *base, baseValid);
    location->locationFlags = 0;
    if (spaceValid && baseValid) {
      location->pose = toXr(worldBase.inverse() * world);
      location->locationFlags =
          XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
          XR_SPACE_LOCATION_POSITION_TRACKED_BIT | XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
    } else {
      location->pose = toXr(Pose{});
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroySpace(XrSpace handle) {
  return guard([&] {
    Space* space = objectOf<Space>(handle);
    if (!space) return XR_ERROR_HANDLE_INVALID;
    space->session->spaces.erase(space);
    gHandles.erase(space);
    delete space;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createActionSet(XrInstance handle, const XrActionSetCreateInfo* info,
                                               XrActionSet* out) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkType(info, XR_TYPE_ACTION_SET_CREATE_INFO);
    if (!out || info->actionSetName[0] == '\0') return XR_ERROR_NAME_INVALID;
    for (const auto& set : instance.actionSets)
      if (set->name == info->actionSetName) return XR_ERROR_NAME_DUPLICATED;
    auto set = std::make_unique<ActionSet>();
    set->name = info->actionSetName;
    *out = handleOf<XrActionSet>(set.get());
    instance.actionSets.insert(std::move(set));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroyActionSet(XrActionSet handle) {
  return guard([&] {
    ActionSet* set = objectOf<ActionSet>(handle);
    if (!set || !gInstance) return XR_ERROR_HANDLE_INVALID;
    for (const auto& action : set->actions) {
      gHandles.erase(action.get());
      for (auto& [profile, bindings] : gInstance->bindings)
        std::erase_if(bindings, [&](const auto& b) { return b.first == action.get(); });
    }
    gHandles.erase(set);
    std::erase_if(gInstance->actionSets, [&](const auto& s) { return s.get() == set; });
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL createAction(XrActionSet handle, const XrActionCreateInfo* info,
                                            XrAction* out) {
  return guard([&] {
    ActionSet* set = objectOf<ActionSet>(handle);
    if (!set || !gInstance) return XR_ERROR_HANDLE_INVALID;
    checkType(info, XR_TYPE_ACTION_CREATE_INFO);
    if (set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    if (!out || info->actionName[0] == '\0') return XR_ERROR_NAME_INVALID;
    auto action = std::make_unique<Action>();
    action->set = set;
    action->name = info->actionName;
    action->type = info->actionType;
    for (std::uint32_t i = 0; i < info->countSubactionPaths; ++i) {
      if (handOf(pathString(*gInstance, info->subactionPaths[i])) < 0 ||
          pathString(*gInstance, info->subactionPaths[i]).find("/input") != std::string::npos)
        return XR_ERROR_PATH_UNSUPPORTED;
      action->subactions.push_back(info->subactionPaths[i]);
    }
    *out = handleOf<XrAction>(action.get());
    set->actions.push_back(std::move(action));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroyAction(XrAction handle) {
  return guard([&] {
    Action* action = objectOf<Action>(handle);
    if (!action) return XR_ERROR_HANDLE_INVALID;
    gHandles.erase(action);  // freed with its set
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL
suggestBindings(XrInstance handle, const XrInteractionProfileSuggestedBinding* suggested) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkType(suggested, XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING);
    const std::string profile = pathString(instance, suggested->interactionProfile);
    if (!knownProfile(profile)) {
      log("suggest " + profile + " unsupported");
      return XR_ERROR_PATH_UNSUPPORTED;
    }
    std::vector<std::pair<Action*, std::string>> bindings;
    for (std::uint32_t i = 0; i < suggested->countSuggestedBindings; ++i) {
      Action& action = actionOf(suggested->suggestedBindings[i].action);
      if (action.set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
      const std::string path = pathString(instance, suggested->suggestedBindings[i].binding);
      if (!bindable(profile, path, action.type)) {
        log("suggest " + profile + " unsupported " + path);
        return XR_ERROR_PATH_UNSUPPORTED;
      }
      bindings.emplace_back(&action, path);
    }
    instance.bindings[profile] = std::move(bindings);  // replaces earlier suggestions
    log("suggest " + profile + " ok");
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL attachActionSets(XrSession handle,
                                                const XrSessionActionSetsAttachInfo* info) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
    Instance& instance = *gInstance;
    if (session.attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    for (std::uint32_t i = 0; i < info->countActionSets; ++i)
      if (!objectOf<ActionSet>(info->actionSets[i])) return XR_ERROR_HANDLE_INVALID;
    session.attached = true;
    for (std::uint32_t i = 0; i < info->countActionSets; ++i)
      objectOf<ActionSet>(info->actionSets[i])->attached = true;
    instance.profile = chosenProfile(instance);
    if (!instance.profile.empty()) profileChanged(instance, session);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getCurrentInteractionProfile(XrSession handle, XrPath user,
                                                            XrInteractionProfileState* state) {
  return guard([&] {
    sessionOf(handle);
    checkType(state, XR_TYPE_INTERACTION_PROFILE_STATE);
    Instance& instance = *gInstance;
    if (handOf(pathString(instance, user)) < 0) return XR_ERROR_PATH_UNSUPPORTED;
    state->interactionProfile = XR_NULL_PATH;
    if (!instance.profile.empty()) {
      XrPath path = XR_NULL_PATH;
      const XrResult result =
          stringToPath(reinterpret_cast<XrInstance>(&instance), instance.profile.c_str(), &path);
      if (XR_FAILED(result)) return result;
      state->interactionProfile = path;
    }
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL syncActions(XrSession handle, const XrActionsSyncInfo* info) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_ACTIONS_SYNC_INFO);
    Instance& instance = *gInstance;
    for (std::uint32_t i = 0; i < info->countActiveActionSets; ++i) {
      ActionSet* set = objectOf<ActionSet>(info->activeActionSets[i].actionSet);
      if (!set) return XR_ERROR_HANDLE_INVALID;
      if (!set->attached) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    }
    session.syncedFocused = session.state == XR_SESSION_STATE_FOCUSED;
    for (const auto& set : instance.actionSets)
      for (const auto& action : set->actions)
        for (int hand = 0; hand < 2; ++hand) {
          const std::optional<float> value =
              session.syncedFocused ? resolve(instance, *action, hand) : std::nullopt;
          action->previous[hand] = action->value[hand];
          action->active[hand] = value.has_value();
          action->value[hand] = value.value_or(0.0f);
          if (action->value[hand] != action->previous[hand]) action->changed[hand] = instance.time;
        }
    return session.syncedFocused ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
  });
}

// The hands an action state is read from: one (a subaction path) or both.
std::vector<int> handsFor(Action& action, XrPath subaction) {
  if (subaction == XR_NULL_PATH) return {0, 1};
  if (std::find(action.subactions.begin(), action.subactions.end(), subaction) ==
      action.subactions.end())
    fail(XR_ERROR_PATH_UNSUPPORTED);
  return {handIndex(*gInstance, subaction)};
}

template <typename State>
Action& readAction(XrSession handle, const XrActionStateGetInfo* info, State* state,
                   XrStructureType type, XrActionType actionType) {
  liveSessionOf(handle);
  checkType(info, XR_TYPE_ACTION_STATE_GET_INFO);
  checkType(state, type);
  Action& action = actionOf(info->action);
  if (action.type != actionType) fail(XR_ERROR_ACTION_TYPE_MISMATCH);
  if (!action.set->attached) fail(XR_ERROR_ACTIONSET_NOT_ATTACHED);
  return action;
}

// A button's or an axis's state over the hands it is read from: active where any hand is, the
// largest value of the active hands (0 where none is), changed where any hand's value changed.
struct HandsState {
  bool active = false;
  float value = 0.0f;
  bool changed = false;
  XrTime lastChangeTime = 0;
};

HandsState readHands(Action& action, XrPath subaction) {
  HandsState state;
  for (int hand : handsFor(action, subaction)) {
    if (!action.active[hand]) continue;
    state.active = true;
    state.value = std::max(state.value, action.value[hand]);
    state.changed |= action.value[hand] != action.previous[hand];
    state.lastChangeTime = std::max(state.lastChangeTime, action.changed[hand]);
  }
  return state;
}

template <typename State, typename Value>
void writeState(State* state, const HandsState& hands, Value current) {
  state->isActive = hands.active ? XR_TRUE : XR_FALSE;
  state->currentState = current;
  state->changedSinceLastSync = hands.changed ? XR_TRUE : XR_FALSE;
  state->lastChangeTime = hands.lastChangeTime;
}

XRAPI_ATTR XrResult XRAPI_CALL getActionStateBoolean(XrSession handle,
                                                     const XrActionStateGetInfo* info,
                                                     XrActionStateBoolean* state) {
  return guard([&] {
    Action& action =
        readAction(handle, info, state, XR_TYPE_ACTION_STATE_BOOLEAN, XR_ACTION_TYPE_BOOLEAN_INPUT);
    const HandsState hands = readHands(action, info->subactionPath);
    writeState(state, hands, hands.value >= 0.5f ? XR_TRUE : XR_FALSE);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getActionStateFloat(XrSession handle,
                                                   const XrActionStateGetInfo* info,
                                                   XrActionStateFloat* state) {
  return guard([&] {
    Action& action =
        readAction(handle, info, state, XR_TYPE_ACTION_STATE_FLOAT, XR_ACTION_TYPE_FLOAT_INPUT);
    const HandsState hands = readHands(action, info->subactionPath);
    writeState(state, hands, hands.value);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getActionStateVector2f(XrSession handle,
                                                      const XrActionStateGetInfo* info,
                                                      XrActionStateVector2f* state) {
  return guard([&] {
    readAction(handle, info, state, XR_TYPE_ACTION_STATE_VECTOR2F, XR_ACTION_TYPE_VECTOR2F_INPUT);
    writeState(state, HandsState{}, XrVector2f{0.0f, 0.0f});  // the user never touches a stick
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL getActionStatePose(XrSession handle,
                                                  const XrActionStateGetInfo* info,
                                                  XrActionStatePose* state) {
  return guard([&] {
    Action& action =
        readAction(handle, info, state, XR_TYPE_ACTION_STATE_POSE, XR_ACTION_TYPE_POSE_INPUT);
    state->isActive = XR_FALSE;
    for (int hand : handsFor(action, info->subactionPath)) state->isActive |= action.active[hand];
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL applyHapticFeedback(XrSession handle, const XrHapticActionInfo* info,
                                                   const XrHapticBaseHeader* haptic) {
  return guard([&] {
    liveSessionOf(handle);
    checkType(info, XR_TYPE_HAPTIC_ACTION_INFO);
    checkType(haptic, XR_TYPE_HAPTIC_VIBRATION);
    Action& action = actionOf(info->action);
    if (action.type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    const auto* vibration = reinterpret_cast<const XrHapticVibration*>(haptic);
    for (int hand : handsFor(action, info->subactionPath))
      if (resolve(*gInstance, action, hand))
        log(std::string("haptic ") + (hand == 0 ? "/user/hand/left" : "/user/hand/right") +
            " amplitude=" + std::to_string(vibration->amplitude) +
            " duration=" + std::to_string(vibration->duration));
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL stopHapticFeedback(XrSession handle,
                                                  const XrHapticActionInfo* info) {
  return guard([&] {
    liveSessionOf(handle);
    checkType(info, XR_TYPE_HAPTIC_ACTION_INFO);
    actionOf(info->action);
    return XR_SUCCESS;
  });
}

}  // namespace curvefold::simxr
