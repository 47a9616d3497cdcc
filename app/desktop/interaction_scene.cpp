#include "app/desktop/interaction_scene.hpp"

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/render/color_map.hpp"
#include "engine/render/scene_builder.hpp"

namespace curvefold::desktop {

glm::mat4 matrixOf(const Pose& pose) {
  return glm::translate(glm::mat4(1.0f), glm::vec3(pose.position)) *
         glm::mat4_cast(glm::quat(pose.orientation));
}

const CreasePatternPanel& CreasePatternCache::panelFor(const FoldSession& session,
                                                       const SceneColors& colors) {
  if (builds_ == 0 || session_ != &session || initial_ != &session.initial() ||
      revision_ != session.designRevision()) {
    panel_ = creasePatternPanel(session.fixed(), colors);
    session_ = &session;
    initial_ = &session.initial();
    revision_ = session.designRevision();
    ++builds_;
  }
  return panel_;
}

namespace {

// The twelve edges of a box with these half extents in the pose's frame, centred at `centre`.
void addBox(std::vector<LineSegment>& lines, const Pose& pose, const glm::dvec3& centre,
            const glm::dvec3& half, const glm::vec4& color) {
  auto corner = [&](int i) {
    const glm::dvec3 sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    return glm::vec3(pose.apply(centre + sign * half));
  };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) lines.push_back({corner(i), corner(i | bit), color});
}

}  // namespace

void addControllerModels(Scene& scene, const InteractionCore& core, const InputFrame& input,
                         const std::optional<Pose>& pointAim) {
  const glm::vec4 idle(0.35f, 0.35f, 0.42f, 1.0f), squeezed(0.6f, 0.3f, 0.8f, 1.0f);
  // OpenXR grip space: the controller's handle runs along -Z; aim space points along -Z.
  if (input.sheetHand.tracked)
    addBox(scene.lines, input.sheetHand.pose, {0.0, 0.0, 0.01}, {0.018, 0.022, 0.055},
           core.clutched() ? squeezed : idle);
  if (!input.pointHand.tracked) return;
  const glm::vec3 tip(input.pointHand.position);
  scene.markers.push_back({tip, 0.006f, {0.95f, 0.95f, 0.98f, 1.0f}});
  if (!pointAim) return;
  addBox(scene.lines, *pointAim, {0.0, -0.01, 0.06}, {0.018, 0.022, 0.055},
         core.twoHanded() ? squeezed : idle);
  scene.lines.push_back({glm::vec3(pointAim->position), tip, {0.9f, 0.9f, 0.95f, 0.8f}});
}

void addHandModel(Scene& scene, const HandJoints& hand, const glm::vec4& color) {
  if (!hand.tracked) return;
  auto at = [&](HandJoint joint) { return glm::vec3(hand[joint].position); };
  for (HandJoint joint : kHandJoints) {
    if (joint == HandJoint::Palm) continue;  // inside the hand
    scene.markers.push_back({at(joint), isFingerTip(joint) ? 0.005f : 0.007f, color});
  }
  // Each finger's chain from the wrist: metacarpal to tip (the thumb has no intermediate).
  for (HandFinger finger : kHandFingers) {
    glm::vec3 from = at(HandJoint::Wrist);
    for (HandJoint joint : fingerJoints(finger)) {
      const glm::vec3 to = at(joint);
      scene.lines.push_back({from, to, color});
      from = to;
    }
  }
}

void addPinchPoint(Scene& scene, const glm::dvec3& point, bool pinched, double openness) {
  const glm::vec4 apart(0.95f, 0.95f, 0.98f, 1.0f), closing(1.0f, 0.8f, 0.1f, 1.0f),
      held(0.2f, 0.85f, 0.35f, 1.0f);
  const float t = float(std::clamp(openness, 0.0, 1.0));
  scene.markers.push_back(
      {glm::vec3(point), pinched ? 0.009f : 0.006f, pinched ? held : glm::mix(closing, apart, t)});
}

namespace {

// Triangles (sheet coordinates) as translucent world triangles, each face shaded by its facing to
// the light from either side, so the shape reads without depth writes.
template <typename Triangles>
void addTranslucentMesh(Scene& scene, const std::vector<glm::dvec3>& positions,
                        const Triangles& triangles, const InteractionCore& core,
                        const glm::vec4& color) {
  const glm::dvec3 light = glm::dvec3(scene.light.direction);
  scene.translucent.reserve(scene.translucent.size() + 3 * triangles.size());
  for (const auto& t : triangles) {
    const glm::dvec3 a = core.worldOf(positions[t[0]]), b = core.worldOf(positions[t[1]]),
                     c = core.worldOf(positions[t[2]]);
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    const double length = glm::length(normal);
    const double facing = length > 0.0 ? std::abs(glm::dot(normal, light)) / length : 0.0;
    const float shade = scene.light.ambient + (1.0f - scene.light.ambient) * float(facing);
    const glm::vec4 shaded(glm::vec3(color) * shade, color.a);
    for (const glm::dvec3& p : {a, b, c}) scene.translucent.push_back({glm::vec3(p), shaded});
  }
}

}  // namespace

void InteractionSheetTracker::update(const InteractionCore& core, SceneRenderer& renderer) {
  if (const LiveSimulation* simulation = core.simulation()) {
    if (simulated_ && simulation == simulation_ &&
        simulationRevision_ == core.session().fixedRevision()) {
      renderer.markSheetMoved();
    } else {
      renderer.markSheetReplaced();
      simulation_ = simulation;
      simulationRevision_ = core.session().fixedRevision();
    }
    simulated_ = true;
    return;
  }
  if (simulated_) {
    tracker_ = SessionSheetTracker(simplify_);
    renderer.markSheetReplaced();
    simulated_ = false;
  }
  tracker_.update(core.session(), renderer);
}

void InteractionSheetTracker::describe(const InteractionCore& core, SceneSheet& sheet,
                                       bool strainColours) {
  const LiveSimulation* simulation = core.simulation();
  if (!simulation) {
    tracker_.describe(sheet);
    return;
  }
  if (!strainColours) return;
  const std::vector<double>& strain = simulation->vertexStrain();
  double largest = 0.0;
  for (double s : strain) largest = std::max(largest, s);
  // A sheet with no strain at all is drawn in the low colour, not the middle of the map.
  colors_ = colorsOf(strain, 0.0, std::max(largest, 1e-12), ColorMap::Viridis);
  sheet.vertexColors = colors_;
}

Scene sceneForInteraction(const InteractionCore& core, const InputFrame& input,
                          const Camera& camera, const Ground& ground,
                          const InteractionSceneOptions& options) {
  const FoldSession& session = core.session();
  // While simulating (issue 39, 4) the simulated sheet is drawn instead of the design, its creases
  // where they have folded to (its strain colours: InteractionSheetTracker::describe).
  const LiveSimulation* simulation = core.simulation();
  const Sheet& sheet = simulation ? simulation->sheet() : session.current();
  const Pose& worldFromSheet = core.worldFromSheet();
  const glm::mat4 model =
      matrixOf(worldFromSheet) * glm::scale(glm::mat4(1.0f), glm::vec3(float(core.viewScale())));
  Scene scene;
  scene.camera = camera;
  scene.ground = ground;
  scene.sheet.sheet = &sheet;
  scene.sheet.worldFromSheet = model;
  if (!simulation) scene.sheet.reflectedTriangles = core.reflectedTriangles();
  scene.creases = creaseLines(sheet, model, scene.colors);
  if (options.creasePatternPanel)
    scene.panel = options.panelCache ? options.panelCache->panelFor(session, scene.colors)
                                     : creasePatternPanel(sheet, scene.colors);
  // Markers keep their size relative to the sheet as it is seen (at the view scale).
  const float size = static_cast<float>(sheetSize(session.initial()) * core.viewScale());
  auto world = [&](const glm::dvec3& p) { return glm::vec3(core.worldOf(p)); };

  if (core.state() == InteractionState::Dragging) {
    scene.markers.push_back({world(core.grabStart()), 0.012f * size, {0.35f, 0.75f, 0.35f, 1}});
    scene.markers.push_back({world(core.grabTarget()), 0.018f * size, {0.95f, 0.45f, 0.1f, 1}});
    if (const std::optional<ReflectionPlane> plane = core.plane())
      scene.plane =
          PlaneDisk{world(plane->point), glm::vec3(worldFromSheet.applyToDirection(plane->normal)),
                    0.35f * size, scene.colors.plane};
    // Triangles the fold passes through the sheet in, outlined (issue 17).
    const glm::vec4 crossing(0.95f, 0.1f, 0.75f, 1.0f);
    for (TriangleIndex t : core.intersectingTriangles()) {
      const Triangle& tri = sheet.triangles[t];
      for (int k = 0; k < 3; ++k)
        scene.lines.push_back(
            {world(sheet.positions[tri[k]]), world(sheet.positions[tri[(k + 1) % 3]]), crossing});
    }
  } else if (const std::optional<HoverPoint>& hover = core.hover()) {
    scene.markers.push_back({world(hover->sheetPosition), 0.015f * size, {1.0f, 0.85f, 0.1f, 1}});
  }
  if (simulation && simulation->pull()) {
    // The pulled point and the spring to the hand.
    const glm::vec4 spring(0.95f, 0.45f, 0.1f, 1.0f);
    const glm::dvec3 from = sheet.positions[simulation->pull()->vertex];
    scene.markers.push_back({world(from), 0.012f * size, spring});
    scene.lines.push_back({world(from), world(simulation->pull()->to), spring});
  }
  if (options.handMarkers && input.pointHand.tracked)
    scene.markers.push_back(
        {glm::vec3(input.pointHand.position), 0.01f * size, {0.2f, 0.2f, 0.25f, 1}});
  if (options.handMarkers && input.sheetHand.tracked)
    scene.markers.push_back(
        {glm::vec3(input.sheetHand.pose.position), 0.03f * size,
         core.clutched() ? glm::vec4(0.6f, 0.3f, 0.8f, 1) : glm::vec4(0.45f, 0.4f, 0.55f, 1)});
  const glm::vec3 toEye = glm::normalize(camera.eye - camera.target);
  scene.light.direction = glm::normalize(toEye + 0.6f * camera.up);

  if (options.target)
    addTranslucentMesh(scene, options.target->positions, options.target->triangles, core,
                       {0.55f, 0.6f, 0.75f, 0.3f});
  // The suggestion on offer: where to grab, where it goes, and what it makes.
  if (const SuggestedFold* offer = core.offeredFold()) {
    const glm::vec4 grabColor(0.1f, 0.75f, 0.55f, 1.0f), dropColor(0.95f, 0.45f, 0.1f, 1.0f);
    scene.markers.push_back({world(offer->grab), 0.014f * size, grabColor});
    scene.markers.push_back({world(offer->to), 0.014f * size, dropColor});
    scene.lines.push_back({world(offer->grab), world(offer->to), grabColor});
    if (options.offeredResult)
      addTranslucentMesh(scene, options.offeredResult->positions, options.offeredResult->triangles,
                         core, {0.2f, 0.8f, 0.55f, 0.35f});
  }
  return scene;
}

}  // namespace curvefold::desktop
