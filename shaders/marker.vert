#version 450
// Markers as sphere impostors: one instance per marker, a view-facing quad around its centre.
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

layout(location = 0) in vec4 inCentreRadius;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec2 local;
layout(location = 1) out vec4 color;

const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1),
                               vec2(-1, 1));

void main() {
  vec2 corner = corners[gl_VertexIndex];
  float radius = inCentreRadius.w;
  vec4 centre = u.view * vec4(inCentreRadius.xyz, 1.0);
  // The quad sits at the sphere's front so a marker on the sheet is not cut in half by it.
  vec4 p = centre + vec4(corner * radius, radius, 0.0);
  gl_Position = u.proj * p;
  local = corner;
  color = inColor;
}
