#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
#include "target_color.glsl"
// The coloured sheet: sheet.frag's flat shading from the position's derivatives, but milder (the
// colour is the message, so shading only darkens it a little to keep the shape readable) and the
// same on both sides.

layout(location = 0) noperspective in vec3 world;
layout(location = 1) in vec3 color;
layout(location = 0) out vec4 outColor;

void main() {
  vec3 normal = -normalize(cross(dFdx(world), dFdy(world)));
  float key = max(dot(normal, u.lightDir.xyz), 0.0);
  vec3 towardViewer = vec3(u.view[VIEW][0][2], u.view[VIEW][1][2], u.view[VIEW][2][2]);
  float head = max(dot(normal, towardViewer), 0.0);
  float shade = 0.7 + 0.3 * (0.6 * key + 0.4 * head);
  outColor = targetColor(vec4(color * shade, 1.0));
}
