#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
// Markers as sphere impostors: one instance per marker, a view-facing quad around its centre.

layout(location = 0) in vec4 inCentreRadius;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec2 local;
layout(location = 1) out vec4 color;

const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1),
                               vec2(-1, 1));

void main() {
  vec2 corner = corners[gl_VertexIndex];
  float radius = inCentreRadius.w;
  vec4 centre = u.view[VIEW] * vec4(inCentreRadius.xyz, 1.0);
  // The quad sits at the sphere's front so a marker on the sheet is not cut in half by it.
  vec4 p = centre + vec4(corner * radius, radius, 0.0);
  gl_Position = u.proj[VIEW] * p;
  local = corner;
  color = inColor;
}
