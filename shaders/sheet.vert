#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
// The sheet: positions in sheet coordinates, placed in the world by the model matrix.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in float inReflected;  // 1 for a vertex only reflected triangles share
// One varying slot: lavapipe sets up interpolation per slot per triangle. Screen-linear
// (noperspective) is enough: the fragment shader uses only its derivatives, which span the
// triangle's plane either way, and the flag's sign.
layout(location = 0) noperspective out vec4 worldAndReflected;

void main() {
  vec4 world = u.model * vec4(inPosition, 1.0);
  worldAndReflected = vec4(world.xyz, inReflected);
  gl_Position = u.viewProj[VIEW] * world;
}
