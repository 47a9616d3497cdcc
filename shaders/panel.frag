#version 450
#extension GL_GOOGLE_include_directive : require
#include "target_color.glsl"
// The panel's picture, sampled as it was drawn (sRGB-encoded colours, like every other colour
// here), opaque.
layout(set = 1, binding = 0) uniform sampler2D picture;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 outColor;

void main() {
  outColor = targetColor(vec4(texture(picture, uv).rgb, 1.0));
}
