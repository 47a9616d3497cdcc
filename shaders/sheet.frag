#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
#include "target_color.glsl"
// Two-sided paper: front and back colours by facing, flat shading from the screen-space
// derivatives of the position (so creases stay sharp), the reflected part tinted: a triangle with
// any vertex that only reflected triangles share interpolates a positive flag everywhere inside.
// (A per-triangle flag through gl_PrimitiveID costs lavapipe twice the frame time.)

// xyz: world position, w: reflected flag; screen-linear (see sheet.vert).
layout(location = 0) noperspective in vec4 worldAndReflected;
layout(location = 0) out vec4 outColor;

void main() {
  // The screen-space derivatives span the triangle's plane; with Vulkan's y-down framebuffer
  // their cross product points away from the eye on either side of the paper, so its negation
  // is the normal of the side seen.
  vec3 normal = -normalize(cross(dFdx(worldAndReflected.xyz), dFdy(worldAndReflected.xyz)));

  vec3 base = gl_FrontFacing ? u.frontColor.rgb : u.backColor.rgb;
  if (worldAndReflected.w > 1e-4)
    base = mix(base, u.tintColor.rgb, u.tintColor.a);

  float key = max(dot(normal, u.lightDir.xyz), 0.0);  // lightDir comes normalized
  // A weak headlight (along the view axis, the view matrix's third row) keeps faces turned away
  // from the key light readable.
  vec3 towardViewer = vec3(u.view[VIEW][0][2], u.view[VIEW][1][2], u.view[VIEW][2][2]);
  float head = max(dot(normal, towardViewer), 0.0);
  float ambient = u.lightDir.w;
  float shade = ambient + (1.0 - ambient) * (0.75 * key + 0.25 * head);
  outColor = targetColor(vec4(base * shade, 1.0));
}
