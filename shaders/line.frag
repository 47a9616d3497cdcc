#version 450
#extension GL_GOOGLE_include_directive : require
#include "target_color.glsl"
layout(location = 0) in vec4 color;
layout(location = 0) out vec4 outColor;

void main() {
  outColor = targetColor(color);
}
