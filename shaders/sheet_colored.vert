#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
// The sheet with a quantity coloured on it (SceneSheet::vertexColors): sheet.vert's position, and
// the vertex's colour interpolated across the triangle.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColor;  // sRGB-encoded, as chosen
layout(location = 0) noperspective out vec3 world;
layout(location = 1) out vec3 color;

void main() {
  vec4 w = u.model * vec4(inPosition, 1.0);
  world = w.xyz;
  color = inColor.rgb;
  gl_Position = u.viewProj[VIEW] * w;
}
