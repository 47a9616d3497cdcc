// Sheet -> Scene helpers: cameras framing a sheet from named views, crease ribbons, the ground
// grid and the crease-pattern panel. Geometry only; the interaction state (markers, plane, hands)
// is added by the caller, which knows it.
#pragma once

#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/render/scene.hpp"

namespace curvefold {

enum class ViewPreset { Iso, Front, Back, Top, Left, Right };

// "iso", "front", "back", "top", "left", "right"; nothing for another name.
std::optional<ViewPreset> parseViewPreset(std::string_view name);
inline constexpr std::string_view kViewPresetNames = "iso, front, back, top, left, right";

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};

  bool empty() const { return min.x > max.x; }
  void add(const glm::vec3& p);
  glm::vec3 centre() const { return 0.5f * (min + max); }
  float radius() const;  // of the bounding sphere around the box
};

Bounds worldBounds(const Sheet& sheet, const glm::mat4& worldFromSheet = glm::mat4(1.0f));

// A camera on the view's side of the bounds (front = +z, the side a flat sheet's front faces;
// top = +y; right = +x; iso = front, right and above), far enough that the bounding sphere fits.
Camera frameBounds(const Bounds& bounds, ViewPreset view, float aspect, float fovYDegrees = 35.0f);
// The same from `direction` (unit, from the bounds' centre towards the eye).
Camera frameBounds(const Bounds& bounds, const glm::vec3& direction, float aspect,
                   float fovYDegrees = 35.0f);

// The unit vector from the target towards the eye for a named view.
glm::vec3 viewDirection(ViewPreset view);

// Crease edges of the sheet as world segments: valleys blue, mountains red, opacity growing with
// |fold angle| (flat creases are left out). Finds each crease's two triangles with one pass over
// the triangles, cheap enough to redo every frame of a drag.
std::vector<LineSegment> creaseLines(const Sheet& sheet, const glm::mat4& worldFromSheet,
                                     const SceneColors& colors);

// The development's boundary (black), slit (green) and creases (red/blue) for the side panel.
CreasePatternPanel creasePatternPanel(const Sheet& sheet, const SceneColors& colors);

// A grid a little below the bounds, centred under them, spaced to their size.
Ground groundBelow(const Bounds& bounds);

// A plain mesh (a target, a shape measured) as a sheet for the renderer: its own positions as the
// development, which only a crease pattern would read; no creases.
Sheet meshSheet(const TriangleMesh& mesh);

// A still image of a sheet: framed camera, creases, ground and (optionally) the panel. The scene
// points at `sheet`, which must outlive it. aspect: of the whole image.
Scene sceneForSheet(const Sheet& sheet, ViewPreset view, float aspect, bool creasePatternPanel);
// The same from `direction` (unit, towards the eye), the sheet placed by worldFromSheet
// (sheet_view.hpp chooses both from the sheet).
Scene sceneForSheet(const Sheet& sheet, const glm::vec3& direction, float aspect,
                    bool creasePatternPanel, const glm::mat4& worldFromSheet = glm::mat4(1.0f));

}  // namespace curvefold
