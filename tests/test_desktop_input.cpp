// The desktop source's mapping (app/desktop/desktop_input.hpp), without a window: rays and
// projection agree, a press on the sheet grabs the point under the mouse, a drag moves it in the
// screen-parallel plane, the wheel moves it in depth, and the frames fold through the core.
#include <gtest/gtest.h>

#include "app/desktop/desktop_input.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "interaction/interaction_core.hpp"

namespace curvefold {
namespace {

constexpr double kWidth = 640, kHeight = 480;

TEST(DesktopInput, RayThroughProjectedPointHitsIt) {
  const Sheet sheet = makeSurface("square");
  const OrbitCamera camera = OrbitCamera::framing(sheet, Pose{}, float(kWidth / kHeight));
  for (const glm::dvec3& p : sheet.positions) {
    const glm::dvec2 pixel = camera.project(p, kWidth, kHeight);
    const Ray ray = camera.ray(pixel, kWidth, kHeight);
    const glm::dvec3 toP = glm::normalize(p - ray.origin);
    EXPECT_NEAR(glm::dot(toP, ray.direction), 1.0, 1e-12);
  }
}

TEST(DesktopInput, DragFoldsThroughTheCore) {
  const Sheet sheet = makeSurface("square");
  FoldSession session(sheet);
  InteractionCore core(session, Pose{});
  const OrbitCamera camera = OrbitCamera::framing(sheet, Pose{}, float(kWidth / kHeight));
  DesktopInput input(0.005);
  const glm::dvec3 corner = sheet.positions[0];
  // Slightly inside the corner, so the ray hits a triangle.
  const glm::dvec2 start = camera.project(0.9 * corner, kWidth, kHeight);
  const Ray ray = camera.ray(start, kWidth, kHeight);
  input.mouseRay(ray, session.current(), core.worldFromSheet());
  core.process(input.frame(0.0));
  EXPECT_EQ(core.state(), InteractionState::Hover);
  ASSERT_TRUE(input.press(ray, session.current(), core.worldFromSheet(), camera.forward()));
  InputFrame frame = input.frame(0.1);
  EXPECT_EQ(frame.pointHand.select, 1.0);
  EXPECT_NEAR(glm::length(frame.pointHand.position - 0.9 * corner), 0.0, 1e-9);
  core.process(frame);
  EXPECT_EQ(core.state(), InteractionState::Dragging);
  // Move to the centre of the view: the tip stays in the plane z = 0 (the screen's, front view).
  const Ray centre = camera.ray({kWidth / 2, kHeight / 2}, kWidth, kHeight);
  input.mouseRay(centre, session.current(), core.worldFromSheet());
  frame = input.frame(0.2);
  EXPECT_NEAR(frame.pointHand.position.z, 0.0, 1e-12);
  input.wheel(2.0);  // away from the viewer: -z in the front view
  frame = input.frame(0.3);
  EXPECT_NEAR(frame.pointHand.position.z, -0.01, 1e-12);
  core.process(frame);
  input.release();
  core.process(input.frame(0.4));
  EXPECT_EQ(session.foldCount(), 1u);
  input.pulse(Button::Undo);
  core.process(input.frame(0.5));
  EXPECT_EQ(session.foldCount(), 0u);
  core.process(input.frame(0.6));  // the pulse lasts one frame
  input.pulse(Button::Redo);
  core.process(input.frame(0.7));
  EXPECT_EQ(session.foldCount(), 1u);
}

TEST(DesktopInput, PressOffTheSheetDoesNothing) {
  const Sheet sheet = makeSurface("square");
  const OrbitCamera camera = OrbitCamera::framing(sheet, Pose{}, float(kWidth / kHeight));
  DesktopInput input;
  const Ray ray = camera.ray({1.0, 1.0}, kWidth, kHeight);
  EXPECT_FALSE(input.press(ray, sheet, Pose{}, camera.forward()));
  EXPECT_FALSE(input.frame(0.0).pointHand.tracked);
}

}  // namespace
}  // namespace curvefold
