#version 450
// Translucent world-space triangles (the reflection plane's disk).
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
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 color;

void main() {
  gl_Position = u.viewProj * vec4(inPosition, 1.0);
  color = inColor;
}
