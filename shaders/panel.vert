#version 450
// A picture on a quad in the world (the headset's panel): two triangles from the corners given
// as push constants; the texture's top-left at corner 0.
// Per-frame values; must match FrameUniforms in engine/render/scene_renderer.cpp.
layout(set = 0, binding = 0) uniform Frame {
  mat4 viewProj;
  mat4 view;
  mat4 proj;
  mat4 model;
  mat4 panelProj;
  vec4 eye;
  vec4 lightDir;
  vec4 frontColor;
  vec4 backColor;
  vec4 tintColor;
  vec4 viewport;
} u;

// Top-left, top-right, bottom-right, bottom-left (world).
layout(push_constant) uniform Corners {
  vec4 corner[4];
} quad;

layout(location = 0) out vec2 uv;

const int kCornerOf[6] = int[6](0, 1, 2, 0, 2, 3);
const vec2 kUv[4] = vec2[4](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));

void main() {
  const int corner = kCornerOf[gl_VertexIndex];
  uv = kUv[corner];
  gl_Position = u.viewProj * vec4(quad.corner[corner].xyz, 1.0);
}
