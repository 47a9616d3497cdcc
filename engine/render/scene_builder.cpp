#include "engine/render/scene_builder.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/topology.hpp"

namespace curvefold {

glm::mat4 Camera::view() const {
  if (viewMatrix) return *viewMatrix;
  return glm::lookAtRH(eye, target, up);
}

glm::mat4 Camera::projection(float aspect) const {
  if (projectionMatrix) return *projectionMatrix;
  glm::mat4 p = glm::perspectiveRH_ZO(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
  p[1][1] *= -1.0f;  // Vulkan's clip space has y down
  return p;
}

std::optional<ViewPreset> parseViewPreset(std::string_view name) {
  if (name == "iso") return ViewPreset::Iso;
  if (name == "front") return ViewPreset::Front;
  if (name == "back") return ViewPreset::Back;
  if (name == "top") return ViewPreset::Top;
  if (name == "left") return ViewPreset::Left;
  if (name == "right") return ViewPreset::Right;
  return std::nullopt;
}

void Bounds::add(const glm::vec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

float Bounds::radius() const {
  return empty() ? 0.0f : 0.5f * glm::length(max - min);
}

Bounds worldBounds(const Sheet& sheet, const glm::mat4& worldFromSheet) {
  Bounds bounds;
  for (const glm::dvec3& p : sheet.positions)
    bounds.add(glm::vec3(worldFromSheet * glm::vec4(glm::vec3(p), 1.0f)));
  return bounds;
}

glm::vec3 viewDirection(ViewPreset view) {
  switch (view) {
    case ViewPreset::Iso:
      return glm::normalize(glm::vec3(0.55f, 0.45f, 1.0f));
    case ViewPreset::Front:
      return {0.0f, 0.0f, 1.0f};
    case ViewPreset::Back:
      return {0.0f, 0.0f, -1.0f};
    case ViewPreset::Top:
      return {0.0f, 1.0f, 0.0f};
    case ViewPreset::Left:
      return {-1.0f, 0.0f, 0.0f};
    case ViewPreset::Right:
      return {1.0f, 0.0f, 0.0f};
  }
  return {0.0f, 0.0f, 1.0f};
}

Camera frameBounds(const Bounds& bounds, ViewPreset view, float aspect, float fovYDegrees) {
  return frameBounds(bounds, viewDirection(view), aspect, fovYDegrees);
}

Camera frameBounds(const Bounds& bounds, const glm::vec3& direction, float aspect,
                   float fovYDegrees) {
  Camera camera;
  camera.fovYDegrees = fovYDegrees;
  const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.centre();
  const float radius = std::max(bounds.radius(), 1e-3f);
  // Straight down (or up) the y axis, y cannot be up: -z is, as the top view has it.
  if (std::abs(direction.y) > 0.999f) camera.up = {0.0f, 0.0f, direction.y > 0.0f ? -1.0f : 1.0f};
  const float halfY = glm::radians(fovYDegrees) * 0.5f;
  const float halfX = std::atan(std::tan(halfY) * aspect);
  const float distance = 1.08f * radius / std::sin(std::min(halfX, halfY));
  camera.target = centre;
  camera.eye = centre + direction * distance;
  camera.nearPlane = std::max(distance - 4.0f * radius, distance * 0.02f);
  camera.farPlane = distance + 40.0f * radius;
  return camera;
}

std::vector<LineSegment> creaseLines(const Sheet& sheet, const glm::mat4& worldFromSheet,
                                     const SceneColors& colors) {
  std::vector<LineSegment> lines;
  if (sheet.tags.empty()) return lines;
  // Only edges between two crease endpoints are looked up among the tags.
  std::vector<std::uint8_t> onCrease(sheet.vertexCount(), 0);
  for (const TaggedEdge& tag : sheet.tags)
    if (tag.kind == EdgeKind::Crease) onCrease[tag.edge.a] = onCrease[tag.edge.b] = 1;
  std::vector<EdgeTopology::EdgeSides> sides(sheet.tags.size());
  for (std::size_t i = 0; i < sides.size(); ++i) sides[i].edge = sheet.tags[i].edge;
  for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t) {
    const Triangle& tri = sheet.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const VertexIndex u = tri[k], v = tri[(k + 1) % 3];
      if (!onCrease[u] || !onCrease[v]) continue;
      const Edge edge = Edge::of(u, v);
      const auto it =
          std::lower_bound(sheet.tags.begin(), sheet.tags.end(), edge,
                           [](const TaggedEdge& tag, const Edge& e) { return tag.edge < e; });
      if (it == sheet.tags.end() || it->edge != edge) continue;
      EdgeTopology::EdgeSides& s = sides[it - sheet.tags.begin()];
      (u < v ? s.left : s.right) = t;  // left runs a->b
      ++s.triangleCount;
    }
  }
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (sheet.tags[i].kind != EdgeKind::Crease || sides[i].triangleCount != 2) continue;
    const double angle = foldAngleDegrees(sheet, sides[i]);
    if (std::abs(angle) < kFlatCreaseDegrees) continue;
    glm::vec4 color = angle > 0.0 ? colors.valley : colors.mountain;
    color.a *= 0.35f + 0.65f * float(std::min(std::abs(angle), 180.0) / 180.0);
    const Edge& e = sides[i].edge;
    lines.push_back({glm::vec3(worldFromSheet * glm::vec4(glm::vec3(sheet.positions[e.a]), 1.0f)),
                     glm::vec3(worldFromSheet * glm::vec4(glm::vec3(sheet.positions[e.b]), 1.0f)),
                     color});
  }
  return lines;
}

CreasePatternPanel creasePatternPanel(const Sheet& sheet, const SceneColors& colors) {
  CreasePatternPanel panel;
  panel.enabled = true;
  if (sheet.vertexCount() == 0) return panel;
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::dvec2& d : sheet.development) {
    lo = glm::min(lo, glm::vec2(d));
    hi = glm::max(hi, glm::vec2(d));
  }
  panel.min = lo;
  panel.max = hi;
  const EdgeTopology edges = buildEdgeTopology(sheet);
  auto flat = [&](VertexIndex v) { return glm::vec3(glm::vec2(sheet.development[v]), 0.0f); };
  for (const EdgeTopology::EdgeSides& s : edges.edges) {
    if (!s.isBoundary()) continue;
    const bool slit = sheet.edgeKind(s.edge) == EdgeKind::Slit;
    panel.lines.push_back({flat(s.edge.a), flat(s.edge.b), slit ? colors.slit : colors.boundary});
  }
  for (const CreaseEdge& crease : creaseEdges(sheet, edges)) {
    if (crease.assignment != Assignment::Mountain && crease.assignment != Assignment::Valley)
      continue;
    glm::vec4 color = crease.assignment == Assignment::Valley ? colors.valley : colors.mountain;
    color.a *= 0.35f + 0.65f * float(std::min(std::abs(crease.foldAngle), 180.0) / 180.0);
    panel.lines.push_back({flat(crease.edge.a), flat(crease.edge.b), color});
  }
  return panel;
}

Ground groundBelow(const Bounds& bounds) {
  Ground ground;
  if (bounds.empty()) return ground;
  const float size = std::max(bounds.radius() * 2.0f, 1e-3f);
  // A round spacing near a tenth of the size: 1, 2 or 5 times a power of ten.
  const float raw = size / 10.0f;
  const float decade = std::pow(10.0f, std::floor(std::log10(raw)));
  const float steps[] = {1.0f, 2.0f, 5.0f, 10.0f};
  ground.spacing = decade;
  for (float step : steps)
    if (decade * step <= raw) ground.spacing = decade * step;
  ground.height = bounds.min.y - 0.15f * size;
  ground.centre = {bounds.centre().x, bounds.centre().z};
  ground.halfCount = 12;
  return ground;
}

Sheet meshSheet(const TriangleMesh& mesh) {
  Sheet sheet;
  sheet.positions = mesh.positions;
  for (const glm::dvec3& p : mesh.positions) sheet.development.push_back({p.x, p.y});
  for (const auto& t : mesh.triangles)
    sheet.triangles.push_back({VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2])});
  return sheet;
}

Scene sceneForSheet(const Sheet& sheet, ViewPreset view, float aspect, bool panel) {
  return sceneForSheet(sheet, viewDirection(view), aspect, panel);
}

Scene sceneForSheet(const Sheet& sheet, const glm::vec3& direction, float aspect, bool panel,
                    const glm::mat4& worldFromSheet) {
  Scene scene;
  scene.sheet.sheet = &sheet;
  scene.sheet.worldFromSheet = worldFromSheet;
  const Bounds bounds = worldBounds(sheet, worldFromSheet);
  if (panel) {
    scene.panel = creasePatternPanel(sheet, scene.colors);
    aspect *= 1.0f - scene.panel.widthFraction;
  }
  scene.camera = frameBounds(bounds, direction, aspect);
  scene.creases = creaseLines(sheet, worldFromSheet, scene.colors);
  scene.ground = groundBelow(bounds);
  // The key light comes from the camera's side, above and to the left, so both sides read.
  const glm::vec3 toEye = glm::normalize(scene.camera.eye - scene.camera.target);
  const glm::vec3 right = glm::normalize(glm::cross(scene.camera.up, toEye));
  scene.light.direction = glm::normalize(toEye + 0.6f * scene.camera.up - 0.5f * right);
  return scene;
}

}  // namespace curvefold
