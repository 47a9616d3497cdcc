// The input and output paths of the interaction profiles the simulated runtime knows, as the
// OpenXR 1.0 specification lists them ("Interaction Profiles"), so that suggested bindings are
// checked the way a real runtime checks them.
#pragma once

#include <string>
#include <string_view>

#include <openxr/openxr.h>

namespace curvefold::simxr {

bool knownProfile(std::string_view profile);

// Whether `path` ("/user/hand/left/input/trigger/value", or a parent such as ".../trigger") is
// an input or output of `profile` that an action of `type` may bind to: poses only to .../pose,
// vibration only to /output/haptic, booleans and floats to scalar components (or their parent),
// 2D vectors to a parent with x and y.
bool bindable(std::string_view profile, std::string_view path, XrActionType type);

// The hand of a /user/hand/... path: 0 left, 1 right, -1 neither; `component` gets the rest.
int handOf(std::string_view path, std::string* component = nullptr);

}  // namespace curvefold::simxr
