#version 450
#extension GL_GOOGLE_include_directive : require
#include "target_color.glsl"
layout(location = 0) in vec2 local;
layout(location = 1) in vec4 color;
layout(location = 0) out vec4 outColor;

void main() {
  float r2 = dot(local, local);
  if (r2 > 1.0) discard;
  // View-space sphere normal, lit from the upper left; a dark rim separates it from the paper.
  vec3 normal = vec3(local, sqrt(1.0 - r2));
  float shade = 0.45 + 0.55 * max(dot(normal, normalize(vec3(-0.4, 0.5, 0.8))), 0.0);
  vec3 rgb = r2 > 0.82 ? color.rgb * 0.35 : color.rgb * shade;
  outColor = targetColor(vec4(rgb, 1.0));
}
