#version 450
#extension GL_GOOGLE_include_directive : require
#include "target_color.glsl"
// Two-sided paper: front and back colours by facing, flat shading from the screen-space
// derivatives of the position (so creases stay sharp), the reflected part tinted: a triangle with
// any vertex that only reflected triangles share interpolates a positive flag everywhere inside.
// (A per-triangle flag through gl_PrimitiveID costs lavapipe twice the frame time.)
// Per-frame values; must match FrameUniforms in engine/render/scene_renderer.cpp.
layout(set = 0, binding = 0) uniform Frame {
  mat4 viewProj;
  mat4 view;
  mat4 proj;
  mat4 model;      // world_from_sheet
  mat4 panelProj;  // development -> panel clip space
  vec4 eye;        // world
  vec4 lightDir;   // world, towards the light; w = ambient
  vec4 frontColor;
  vec4 backColor;
  vec4 tintColor;  // rgb; a = how much of it the reflected part takes
  vec4 viewport;   // width, height in pixels
} u;

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
  vec3 towardViewer = vec3(u.view[0][2], u.view[1][2], u.view[2][2]);
  float head = max(dot(normal, towardViewer), 0.0);
  float ambient = u.lightDir.w;
  float shade = ambient + (1.0 - ambient) * (0.75 * key + 0.25 * head);
  outColor = targetColor(vec4(base * shade, 1.0));
}
