#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
// Translucent world-space triangles (the reflection plane's disk).

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 color;

void main() {
  gl_Position = u.viewProj[VIEW] * vec4(inPosition, 1.0);
  color = inColor;
}
