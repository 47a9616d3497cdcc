#include "sim_input/xr_runtime/profile_paths.hpp"

#include <algorithm>
#include <initializer_list>
#include <vector>

namespace curvefold::simxr {

namespace {

struct ProfilePaths {
  std::string_view profile;
  std::initializer_list<std::string_view> both, leftOnly, rightOnly;
};

// Components under /user/hand/<hand>, from the specification.
const ProfilePaths kProfiles[] = {
    {"/interaction_profiles/khr/simple_controller",
     {"/input/select/click", "/input/menu/click", "/input/grip/pose", "/input/aim/pose",
      "/output/haptic"},
     {},
     {}},
    {"/interaction_profiles/htc/vive_controller",
     {"/input/system/click", "/input/squeeze/click", "/input/menu/click", "/input/trigger/click",
      "/input/trigger/value", "/input/trackpad/x", "/input/trackpad/y", "/input/trackpad/click",
      "/input/trackpad/touch", "/input/grip/pose", "/input/aim/pose", "/output/haptic"},
     {},
     {}},
    {"/interaction_profiles/microsoft/motion_controller",
     {"/input/menu/click", "/input/squeeze/click", "/input/trigger/value", "/input/thumbstick/x",
      "/input/thumbstick/y", "/input/thumbstick/click", "/input/trackpad/x", "/input/trackpad/y",
      "/input/trackpad/click", "/input/trackpad/touch", "/input/grip/pose", "/input/aim/pose",
      "/output/haptic"},
     {},
     {}},
    {"/interaction_profiles/oculus/touch_controller",
     {"/input/squeeze/value", "/input/trigger/value", "/input/trigger/touch", "/input/thumbstick/x",
      "/input/thumbstick/y", "/input/thumbstick/click", "/input/thumbstick/touch",
      "/input/thumbrest/touch", "/input/grip/pose", "/input/aim/pose", "/output/haptic"},
     {"/input/x/click", "/input/x/touch", "/input/y/click", "/input/y/touch", "/input/menu/click"},
     {"/input/a/click", "/input/a/touch", "/input/b/click", "/input/b/touch",
      "/input/system/click"}},
    {"/interaction_profiles/valve/index_controller",
     {"/input/system/click",   "/input/system/touch",     "/input/a/click",
      "/input/a/touch",        "/input/b/click",          "/input/b/touch",
      "/input/squeeze/value",  "/input/squeeze/force",    "/input/trigger/click",
      "/input/trigger/value",  "/input/trigger/touch",    "/input/thumbstick/x",
      "/input/thumbstick/y",   "/input/thumbstick/click", "/input/thumbstick/touch",
      "/input/trackpad/x",     "/input/trackpad/y",       "/input/trackpad/force",
      "/input/trackpad/touch", "/input/grip/pose",        "/input/aim/pose",
      "/output/haptic"},
     {},
     {}},
};

const ProfilePaths* find(std::string_view profile) {
  for (const ProfilePaths& p : kProfiles)
    if (p.profile == profile) return &p;
  return nullptr;
}

std::vector<std::string_view> componentsOf(const ProfilePaths& p, int hand) {
  std::vector<std::string_view> all(p.both);
  const auto& extra = hand == 0 ? p.leftOnly : p.rightOnly;
  all.insert(all.end(), extra.begin(), extra.end());
  return all;
}

}  // namespace

bool knownProfile(std::string_view profile) {
  return find(profile) != nullptr;
}

int handOf(std::string_view path, std::string* component) {
  for (int hand = 0; hand < 2; ++hand) {
    const std::string_view prefix = hand == 0 ? "/user/hand/left" : "/user/hand/right";
    if (path.starts_with(prefix) && (path.size() == prefix.size() || path[prefix.size()] == '/')) {
      if (component) *component = std::string(path.substr(prefix.size()));
      return hand;
    }
  }
  return -1;
}

bool bindable(std::string_view profile, std::string_view path, XrActionType type) {
  const ProfilePaths* p = find(profile);
  std::string component;
  const int hand = handOf(path, &component);
  if (!p || hand < 0) return false;
  const std::vector<std::string_view> components = componentsOf(*p, hand);
  const bool exact = std::find(components.begin(), components.end(), component) != components.end();
  auto child = [&](std::string_view name) {
    return std::find(components.begin(), components.end(), component + "/" + std::string(name)) !=
           components.end();
  };
  const bool parent = !exact && std::any_of(components.begin(), components.end(),
                                            [&](auto c) { return c.starts_with(component + "/"); });
  const bool isPose = component.ends_with("/pose");
  const bool isHaptic = component == "/output/haptic";
  switch (type) {
    case XR_ACTION_TYPE_POSE_INPUT:
      return exact && isPose;
    case XR_ACTION_TYPE_VIBRATION_OUTPUT:
      return exact && isHaptic;
    case XR_ACTION_TYPE_VECTOR2F_INPUT:
      return parent && child("x") && child("y");
    case XR_ACTION_TYPE_BOOLEAN_INPUT:
    case XR_ACTION_TYPE_FLOAT_INPUT:
      if (exact) return !isPose && !isHaptic;
      // A parent stands for its value, click or force component.
      return parent && (child("value") || child("click") || child("force"));
    default:
      return false;
  }
}

}  // namespace curvefold::simxr
