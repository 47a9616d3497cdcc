#version 450
// The sheet: positions in sheet coordinates, placed in the world by the model matrix.
// Per-frame values; must match FrameUniforms in engine/render/scene_renderer.cpp.
layout(set = 0, binding = 0) uniform Frame {
  mat4 viewProj;
  mat4 view;
  mat4 proj;
  mat4 model;      // world_from_sheet
  mat4 panelProj;  // development -> panel clip space
  vec4 eye;        // world
  vec4 lightDir;   // world, towards the light; w = ambient
  vec4 frontColor;
  vec4 backColor;
  vec4 tintColor;  // rgb; a = how much of it the reflected part takes
  vec4 viewport;   // width, height in pixels
} u;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in float inReflected;  // 1 for a vertex only reflected triangles share
// One varying slot: lavapipe sets up interpolation per slot per triangle. Screen-linear
// (noperspective) is enough: the fragment shader uses only its derivatives, which span the
// triangle's plane either way, and the flag's sign.
layout(location = 0) noperspective out vec4 worldAndReflected;

void main() {
  vec4 world = u.model * vec4(inPosition, 1.0);
  worldAndReflected = vec4(world.xyz, inReflected);
  gl_Position = u.viewProj * world;
}
