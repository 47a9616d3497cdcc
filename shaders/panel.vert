#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
// A picture on a quad in the world (the headset's panel): two triangles of world positions with
// their texture coordinates (the picture's top-left at uv 0, 0).

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 0) out vec2 uv;

void main() {
  uv = inUv;
  gl_Position = u.viewProj[VIEW] * vec4(inPosition, 1.0);
}
