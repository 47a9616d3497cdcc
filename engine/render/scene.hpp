// A plain description of what to draw (docs/design.md 7): no interaction, XR or Vulkan types, so
// the desktop designer, the replay frames and the XR eyes all fill the same struct. World units are
// metres; the sheet is given in sheet coordinates with its world_from_sheet matrix.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <glm/ext/vector_uint4_sized.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 1.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDegrees = 35.0f;
  float nearPlane = 0.01f;
  float farPlane = 100.0f;
  // An XR eye gives its own matrices (a pose and an asymmetric frustum); eye and target still
  // say where it is and looks, for lighting.
  std::optional<glm::mat4> viewMatrix;
  std::optional<glm::mat4> projectionMatrix;

  glm::mat4 view() const;
  // Vulkan clip space: y down, depth 0 (near) to 1 (far).
  glm::mat4 projection(float aspect) const;
};

struct Light {
  glm::vec3 direction{-0.4f, 0.8f, 0.6f};  // world, towards the light
  float ambient = 0.35f;
};

struct SceneColors {
  glm::vec3 front{0.96f, 0.95f, 0.91f};  // paper white
  glm::vec3 back{0.96f, 0.56f, 0.26f};   // soft orange, like origami paper's coloured side
  glm::vec4 reflectedTint{0.45f, 0.70f, 1.0f, 0.35f};  // rgb, a = strength [MI Fig. 4]
  glm::vec3 background{0.86f, 0.88f, 0.91f};
  glm::vec4 mountain{0.86f, 0.08f, 0.08f, 1.0f};
  glm::vec4 valley{0.08f, 0.22f, 0.95f, 1.0f};
  glm::vec4 boundary{0.1f, 0.1f, 0.1f, 1.0f};
  glm::vec4 slit{0.0f, 0.7f, 0.0f, 1.0f};
  glm::vec4 grid{0.55f, 0.58f, 0.62f, 0.7f};
  glm::vec4 plane{0.35f, 0.65f, 1.0f, 0.25f};
  glm::vec3 panelBackground{0.97f, 0.97f, 0.95f};
};

// The sheet, drawn from the Sheet itself (the renderer converts its doubles to floats). Which
// parts of the GPU copy are stale is told to the SceneRenderer (markSheetChanged/Replaced).
struct SceneSheet {
  const Sheet* sheet = nullptr;
  glm::mat4 worldFromSheet{1.0f};
  std::span<const TriangleIndex> reflectedTriangles;  // tinted; any order
  // A quantity coloured on the sheet (color_map.hpp): one sRGB colour per vertex, interpolated
  // across each triangle and shaded, in place of the paper's two sides and the tint. Empty: paper.
  // Uploaded whole each frame it is given (pictures, not a live drag); its size must be the
  // sheet's vertex count (else it is ignored).
  std::span<const glm::u8vec4> vertexColors;
};

struct LineSegment {
  glm::vec3 a{0.0f};
  glm::vec3 b{0.0f};
  glm::vec4 color{0.0f, 0.0f, 0.0f, 1.0f};  // alpha: opacity (crease: by |fold angle|)
};

// A sphere: the grabbed handle, its start, the hover highlight, a hand or controller.
struct Marker {
  glm::vec3 position{0.0f};
  float radius = 0.004f;
  glm::vec4 color{1.0f};
};

// The reflection plane while dragging, as a translucent disk.
struct PlaneDisk {
  glm::vec3 centre{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  float radius = 0.1f;
  glm::vec4 color{0.35f, 0.65f, 1.0f, 0.25f};
};

// A corner of a translucent world triangle.
struct TranslucentVertex {
  glm::vec3 position{0.0f};
  glm::vec4 color{1.0f};  // alpha: opacity
};

// A square grid of lines in the plane y = height, centred under the sheet.
struct Ground {
  bool enabled = true;
  float height = 0.0f;
  glm::vec2 centre{0.0f};  // x, z
  float spacing = 0.05f;
  int halfCount = 10;  // lines each side of the centre
};

// The 2D crease pattern drawn in a screen-space region at the right of the image.
struct CreasePatternPanel {
  bool enabled = false;
  float widthFraction = 0.34f;     // of the image width
  glm::vec2 min{0.0f}, max{1.0f};  // development bounds to fit
  std::vector<LineSegment> lines;  // development coordinates in a and b (z = 0)
};

// A picture on a quad in the world (the headset's panel), drawn from the texture the renderer
// was given (SceneRenderer::setWorldPanelTexture); corners top-left, top-right, bottom-right,
// bottom-left, the picture's top-left at the first.
struct WorldPanel {
  glm::vec3 corners[4]{};
};

struct Scene {
  Camera camera;
  // A multiview pass's second view (the right eye; the first is `camera`).
  std::optional<Camera> secondView;
  Light light;
  SceneColors colors;
  SceneSheet sheet;
  std::vector<LineSegment> creases;  // world; drawn over the sheet
  std::vector<LineSegment> lines;    // other world lines (the plane's rim), thin
  std::vector<Marker> markers;
  std::optional<PlaneDisk> plane;
  // Translucent world triangles, three corners each (a target shape's ghost, a suggested fold's
  // result): drawn over the opaque scene, hiding nothing behind them.
  std::vector<TranslucentVertex> translucent;
  Ground ground;
  CreasePatternPanel panel;
  std::optional<WorldPanel> worldPanel;
  float creaseWidthPixels = 3.0f;
  float lineWidthPixels = 1.5f;
};

}  // namespace curvefold
