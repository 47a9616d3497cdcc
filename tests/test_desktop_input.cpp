// The desktop source's mapping (app/desktop/desktop_input.hpp), without a window: rays and
// projection agree, a press on the sheet grabs the point under the mouse, a drag moves it in the
// screen-parallel plane, the wheel moves it in depth, and the frames fold through the core.
#include <chrono>

#include <gtest/gtest.h>

#include "app/desktop/desktop_input.hpp"
#include "app/desktop/interaction_scene.hpp"
#include "app/desktop/redraw_pacer.hpp"
#include "engine/render/color_map.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "interaction/interaction_core.hpp"
#include "interaction/live_simulation.hpp"
#include "sim_input/simulated_hand.hpp"

namespace curvefold::desktop {
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

// Issue 38, 4: `design square --target T.obj`, T a tall cylinder's shape, opened on the square
// with the target mostly out of view. The view frames the sheet and the target together: both
// boxes lie inside it, at the window's aspect, wide or tall.
TEST(DesktopInput, TheViewFramesTheSheetWithTheTarget) {
  const Sheet square = makeSurface("square");
  const TriangleMesh target = meshOf(makeSurface("cylinder", {{"radius", 0.12}, {"height", 0.5}}));
  const Bounds sheetBox = studioBounds(square, nullptr, Pose{});
  const Bounds both = studioBounds(square, &target, Pose{});
  Bounds targetBox;
  for (const glm::dvec3& p : target.positions) targetBox.add(glm::vec3(p));
  for (const glm::dvec2 size : {glm::dvec2(1280, 720), glm::dvec2(640, 900)}) {
    const float aspect = float(size.x / size.y);
    // The sheet's own framing leaves the target out: the case is real.
    EXPECT_FALSE(OrbitCamera::framing(square, Pose{}, aspect).shows(targetBox, size.x, size.y));
    const OrbitCamera camera = OrbitCamera::framing(both, aspect);
    EXPECT_TRUE(camera.shows(sheetBox, size.x, size.y)) << size.x << "x" << size.y;
    EXPECT_TRUE(camera.shows(targetBox, size.x, size.y)) << size.x << "x" << size.y;
  }
}

// Issue 38, 4: after Take the sheet left the view. A fold that takes a sheet the view showed
// whole out of it frames the sheet with the target again; a view zoomed into the sheet (which
// did not show it whole) stays as the user left it.
TEST(DesktopInput, AFoldThatTakesTheSheetOutOfViewFramesItAgain) {
  const Sheet square = makeSurface("square");
  const TriangleMesh target = meshOf(makeSurface("cylinder", {{"radius", 0.12}, {"height", 0.5}}));
  const double width = 1280, height = 720;
  const OrbitCamera start = OrbitCamera::framing(square, Pose{}, float(width / height));
  // The sheet after a fold that lifted it up into the target.
  Bounds moved;
  moved.add({-0.1f, 0.1f, -0.05f});
  moved.add({0.1f, 0.35f, 0.05f});
  Bounds both = moved;
  for (const glm::dvec3& p : target.positions) both.add(glm::vec3(p));
  ASSERT_FALSE(start.shows(moved, width, height));  // the case is real
  OrbitCamera camera = start;
  EXPECT_TRUE(followSheet(camera, true, moved, both, width, height));
  EXPECT_TRUE(camera.shows(moved, width, height));
  EXPECT_TRUE(camera.shows(both, width, height));
  OrbitCamera zoomed = start;
  zoomed.zoom(5.0);
  const OrbitCamera before = zoomed;
  EXPECT_FALSE(followSheet(zoomed, false, moved, both, width, height));
  EXPECT_EQ(zoomed.distance, before.distance);
  EXPECT_EQ(zoomed.target, before.target);
}

// The panel's "strain" colours the simulated sheet (issue 39, 4): a colour per vertex, the most
// strained in the map's high end and the least in its low end; nothing without "strain" or while
// the design is shown.
TEST(InteractionSheetTracker, StrainColoursTheSimulatedSheet) {
  const Sheet cylinder = makeSurface("cylinder", {{"resolution", 8}});
  FoldSession session(cylinder);
  InteractionCore core(session, Pose{});
  InteractionSheetTracker tracker;
  SceneSheet shown;
  tracker.describe(core, shown, /*strainColours=*/true);
  EXPECT_TRUE(shown.vertexColors.empty());  // the design, not simulated: paper
  InputFrame frame;
  // A few frames from flat toward the design with a corner pulled: strained (a pull also keeps
  // the live predictor off, which would give the cylinder's unstrained shape at 60% at once).
  for (int i = 0; i < 3; ++i) {
    frame.time += 1.0 / 60.0;
    frame.simulation = liveSimulationInput(60.0, session.fixed());
    frame.simulation->pull =
        SimulationPull{0, session.fixed().positions[0] + glm::dvec3(0.0, 0.0, 0.05)};
    core.process(frame);
  }
  ASSERT_NE(core.simulation(), nullptr);
  SceneSheet plain;
  tracker.describe(core, plain, /*strainColours=*/false);
  EXPECT_TRUE(plain.vertexColors.empty());
  SceneSheet coloured;
  tracker.describe(core, coloured, /*strainColours=*/true);
  const std::vector<double> strain = core.simulation()->vertexStrain();
  ASSERT_EQ(coloured.vertexColors.size(), core.simulation()->sheet().vertexCount());
  ASSERT_EQ(strain.size(), coloured.vertexColors.size());
  const auto most = std::max_element(strain.begin(), strain.end()) - strain.begin();
  const auto least = std::min_element(strain.begin(), strain.end()) - strain.begin();
  ASSERT_GT(strain[most], strain[least]);
  EXPECT_EQ(coloured.vertexColors[most], colorAt(ColorMap::Viridis, 1.0));
  EXPECT_EQ(coloured.vertexColors[least], colorAt(ColorMap::Viridis, strain[least] / strain[most]));
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
}  // namespace curvefold::desktop

namespace curvefold::desktop {
namespace {

// Issue 14, 5: the crease pattern panel is built once per design change (commit, undo, redo, a new
// session), not every frame nor on a grab, and it is the committed design's pattern.
TEST(CreasePatternCache, BuildsOncePerDesignChange) {
  FoldSession session(makeSurface("square", {{"resolution", 16}}));
  CreasePatternCache cache;
  const SceneColors colors;
  EXPECT_TRUE(cache.panelFor(session, colors).lines.size() > 0);  // the outline
  cache.panelFor(session, colors);
  EXPECT_EQ(cache.builds(), 1u);
  const glm::dvec3 grabbed = session.beginDragNear({0.08, 0.08, 0.0});
  session.updateDrag(grabbed + glm::dvec3(-0.02, 0.0, 0.05));
  cache.panelFor(session, colors);
  EXPECT_EQ(cache.builds(), 1u);  // a grab and a drag change no committed crease
  ASSERT_TRUE(session.commit());
  const CreasePatternPanel& folded = cache.panelFor(session, colors);
  EXPECT_EQ(cache.builds(), 2u);
  EXPECT_EQ(folded.lines.size(), creasePatternPanel(session.fixed(), colors).lines.size());
  EXPECT_GT(folded.lines.size(), creasePatternPanel(session.initial(), colors).lines.size());
  session.undo();
  EXPECT_EQ(cache.panelFor(session, colors).lines.size(),
            creasePatternPanel(session.initial(), colors).lines.size());
  EXPECT_EQ(cache.builds(), 3u);
  FoldSession other(makeSurface("disk", {{"resolution", 8}}));
  cache.panelFor(other, colors);
  EXPECT_EQ(cache.builds(), 4u);
}

}  // namespace
}  // namespace curvefold::desktop

namespace curvefold::desktop {
namespace {

// Issue 14, 3: the headset draws the controllers as simple generic models: a grip body at the
// sheet hand (lit while it holds the sheet), and for the point hand a body behind its aim pose, a
// pointer to the tip and the tip itself.
TEST(ControllerModels, GripBodyPointerAndTip) {
  FoldSession session(makeSurface("square", {{"resolution", 4}}));
  InteractionCore core(session, defaultSheetFrame());
  InputFrame input;
  input.sheetHand.tracked = true;
  input.sheetHand.pose = {{-0.2, 1.0, -0.3}, glm::dquat(1, 0, 0, 0)};
  input.pointHand.tracked = true;
  const Pose aim{{0.2, 1.0, -0.3}, glm::angleAxis(0.3, glm::dvec3(0, 1, 0))};
  input.pointHand.position = aim.apply({0.0, 0.0, -0.05});
  core.process(input);

  Scene scene;
  addControllerModels(scene, core, input, aim);
  ASSERT_EQ(scene.lines.size(), 12u + 12u + 1u);  // two boxes and the pointer
  ASSERT_EQ(scene.markers.size(), 1u);
  EXPECT_LT(glm::distance(glm::dvec3(scene.markers[0].position), input.pointHand.position), 1e-6);
  const LineSegment& pointer = scene.lines.back();
  EXPECT_LT(glm::distance(glm::dvec3(pointer.a), aim.position), 1e-6);
  EXPECT_LT(glm::distance(glm::dvec3(pointer.b), input.pointHand.position), 1e-6);
  // The sheet hand's body sits around its grip pose, about a hand's size.
  for (int i = 0; i < 12; ++i)
    EXPECT_LT(glm::distance(glm::dvec3(scene.lines[i].a), input.sheetHand.pose.position), 0.1);
  const glm::vec4 idle = scene.lines[0].color;
  input.sheetHand.clutch = 1.0;
  core.process(input);
  Scene held;
  addControllerModels(held, core, input, std::nullopt);  // no aim pose: body, tip, no pointer
  ASSERT_EQ(held.lines.size(), 12u);
  EXPECT_NE(held.lines[0].color, idle);
  EXPECT_EQ(held.markers.size(), 1u);
}

// Issue 16, 2: a tracked bare hand is drawn as its joints (a sphere each, tips smaller) and bones
// (a line from the wrist down each finger); an untracked one not at all. The pinch point shows
// its state: white apart, yellow closing, green and larger pinched.
TEST(HandModels, JointsBonesAndThePinchState) {
  const HandJoints hand =
      simulatedHand(Pose{{0.0, 1.0, -0.3}, glm::dquat(1, 0, 0, 0)}, HandSide::Right, {});
  const glm::vec4 color(0.5f, 0.5f, 0.6f, 1.0f);
  Scene scene;
  addHandModel(scene, hand, color);
  ASSERT_EQ(scene.markers.size(), 25u);  // every joint but the palm
  ASSERT_EQ(scene.lines.size(), 24u);    // thumb 4 bones, fingers 5 each
  for (std::size_t i = 0; i < scene.markers.size(); ++i) {
    EXPECT_LT(glm::distance(glm::dvec3(scene.markers[i].position), hand.joints[i + 1].position),
              1e-6);
    EXPECT_EQ(scene.markers[i].color, color);
  }
  // Every bone ends on a joint and is shorter than a hand.
  for (const LineSegment& bone : scene.lines) EXPECT_LT(glm::distance(bone.a, bone.b), 0.1f);
  Scene none;
  addHandModel(none, HandJoints{}, color);
  EXPECT_TRUE(none.markers.empty() && none.lines.empty());

  Scene apart, closing, pinched;
  addPinchPoint(apart, {0, 1, 0}, false, 1.0);
  addPinchPoint(closing, {0, 1, 0}, false, 0.0);
  addPinchPoint(pinched, {0, 1, 0}, true, 0.0);
  ASSERT_EQ(apart.markers.size(), 1u);
  EXPECT_GT(apart.markers[0].color.b, 0.9f);                          // white
  EXPECT_LT(closing.markers[0].color.b, 0.2f);                        // yellow
  EXPECT_GT(pinched.markers[0].color.g, pinched.markers[0].color.r);  // green
  EXPECT_GT(pinched.markers[0].radius, apart.markers[0].radius);
}

// The window's pacing (issue 38, 3), on a clock of its own: a change is drawn at once and for the
// settling frames after it, then the window rests, looking again within kStudioCheckSeconds, and
// draws again after kSeldomRedrawSeconds; something moving is drawn every frame.
TEST(RedrawPacer, DrawsAChangeThenRestsUntilTheNextOrTheSeldomRedraw) {
  using Clock = RedrawPacer::Clock;
  const Clock::time_point t0{};
  const auto at = [&](double seconds) {
    return t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  };
  RedrawPacer pacer;
  pacer.changed();
  int drawn = 0;
  for (double t = 0.0; pacer.due(at(t)) && drawn < 100; t += 0.001) {
    pacer.drawn(false, at(t));
    ++drawn;
  }
  EXPECT_EQ(drawn, RedrawPacer::kSettleFrames);
  const double last = 0.001 * (drawn - 1);
  EXPECT_FALSE(pacer.due(at(last + 0.1)));
  EXPECT_LE(pacer.wait(at(last + 0.1)), RedrawPacer::kStudioCheckSeconds);
  EXPECT_GT(pacer.wait(at(last + 0.1)), 0.0);
  EXPECT_TRUE(pacer.due(at(last + RedrawPacer::kSeldomRedrawSeconds)));
  pacer.drawn(true, at(1.0));  // moving: the next frame at once
  EXPECT_TRUE(pacer.due(at(1.0)));
  EXPECT_EQ(pacer.wait(at(1.0)), 0.0);
  pacer.drawn(false, at(1.01));
  EXPECT_FALSE(pacer.due(at(1.02)));
  pacer.changed();
  EXPECT_TRUE(pacer.due(at(1.02)));
}

}  // namespace
}  // namespace curvefold::desktop
