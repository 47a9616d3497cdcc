// The XR pieces that need no runtime: CHECK_XR's message, the eye frustum, the controls table.
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "app/xr/xr_vulkan_graphics.hpp"
#include "interaction/xr/xr_check.hpp"
#include "interaction/xr/xr_input.hpp"
#include "interaction/xr_controls.hpp"

namespace curvefold {
namespace {

TEST(XrCheck, ThrowsWithTheCallTheResultAndTheLine) {
  EXPECT_EQ(CHECK_XR(XR_SUCCESS), XR_SUCCESS);
  EXPECT_EQ(CHECK_XR(XR_SESSION_LOSS_PENDING), XR_SESSION_LOSS_PENDING);  // a success code
  const int line = __LINE__ + 2;
  try {
    CHECK_XR(XrResult(XR_ERROR_SESSION_LOST));
    FAIL() << "no throw";
  } catch (const XrError& e) {
    EXPECT_EQ(e.result(), XR_ERROR_SESSION_LOST);
    const std::string message = e.what();
    EXPECT_NE(message.find("XrResult(XR_ERROR_SESSION_LOST)"), std::string::npos) << message;
    EXPECT_NE(message.find("failed with XR_ERROR_SESSION_LOST"), std::string::npos) << message;
    EXPECT_NE(message.find("test_xr_parts.cpp:" + std::to_string(line)), std::string::npos)
        << message;
  }
  EXPECT_EQ(xrResultName(XrResult(-123456)), "XrResult(-123456)");
}

TEST(XrEyeCamera, TheFrustumEdgesLandOnTheImageEdges) {
  XrPosef pose{};
  const glm::quat turn = glm::angleAxis(0.3f, glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f)));
  pose.orientation = {turn.x, turn.y, turn.z, turn.w};
  pose.position = {0.1f, 1.6f, 0.3f};
  const XrFovf fov{-0.87f, 0.79f, 0.84f, -0.91f};  // left, right, up, down
  const Camera camera = xr::eyeCamera(pose, fov, 0.05f, 50.0f);
  const glm::mat4 clipFromWorld = camera.projection(1.0f) * camera.view();
  auto ndc = [&](const glm::vec3& eyeDirection, float distance) {
    const glm::vec3 world = glm::vec3(pose.position.x, pose.position.y, pose.position.z) +
                            turn * (eyeDirection * distance);
    const glm::vec4 clip = clipFromWorld * glm::vec4(world, 1.0f);
    return glm::vec3(clip) / clip.w;
  };
  // Directions along the four half-angles (eye space looks down -Z).
  EXPECT_NEAR(ndc({std::tan(fov.angleRight), 0, -1}, 2.0f).x, 1.0f, 1e-4f);
  EXPECT_NEAR(ndc({std::tan(fov.angleLeft), 0, -1}, 2.0f).x, -1.0f, 1e-4f);
  EXPECT_NEAR(ndc({0, std::tan(fov.angleUp), -1}, 2.0f).y, -1.0f, 1e-4f);  // Vulkan: y down
  EXPECT_NEAR(ndc({0, std::tan(fov.angleDown), -1}, 2.0f).y, 1.0f, 1e-4f);
  EXPECT_NEAR(ndc({0, 0, -1}, 0.05f).z, 0.0f, 1e-4f);  // near plane -> depth 0
  EXPECT_NEAR(ndc({0, 0, -1}, 50.0f).z, 1.0f, 1e-4f);  // far plane -> depth 1
  // Lighting still knows where the eye is and looks.
  EXPECT_NEAR(camera.eye.y, 1.6f, 1e-6f);
  EXPECT_GT(glm::dot(camera.target - camera.eye, turn * glm::vec3(0, 0, -1)), 0.99f);
}

TEST(XrControls, EveryProfileHoldsThePosesAndFoldsOnBothHands) {
  std::set<std::string> profiles;
  for (const XrProfileControls& profile : xrProfileControls()) {
    SCOPED_TRACE(std::string(profile.profile));
    profiles.insert(std::string(profile.profile));
    for (XrControl needed :
         {XrControl::GripPose, XrControl::AimPose, XrControl::Clutch, XrControl::Select,
          XrControl::Undo, XrControl::Cancel, XrControl::Haptic})
      for (std::string_view hand : {"left", "right"}) {
        bool found = false;
        for (const XrControlBinding& binding : profile.bindings)
          found |= binding.control == needed && binding.hand == hand;
        // Either hand may hold the sheet or the point, so every role control is on both.
        EXPECT_TRUE(found) << int(needed) << " on " << hand;
      }
    for (const XrControlBinding& binding : profile.bindings) {
      EXPECT_TRUE(binding.input.starts_with("/input/") || binding.input == "/output/haptic");
      EXPECT_EQ(binding.control == XrControl::Haptic, binding.input == "/output/haptic");
    }
  }
  EXPECT_EQ(profiles.size(), 5u);
  EXPECT_EQ(sheetHandSide(HandSide::Right), HandSide::Left);
  EXPECT_EQ(pointHandSide(HandSide::Left), HandSide::Left);
}

}  // namespace
}  // namespace curvefold
