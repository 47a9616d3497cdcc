#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
// Lines as screen-space ribbons: one instance per segment, six vertices expanded to a quad
// widthPixels wide (with square caps), so lines keep their width at any distance. World lines are
// pulled a little toward the eye so the surface they lie on does not hide them.

layout(push_constant) uniform Push {
  vec2 viewportSize;  // pixels of the viewport drawn into
  float widthPixels;
  float towardEye;  // fraction of the distance to the eye
  uint space;       // 0: world, 1: crease-pattern panel (development coordinates)
} pc;

layout(location = 0) in vec3 inA;
layout(location = 1) in vec3 inB;
layout(location = 2) in vec4 inColor;
layout(location = 0) out vec4 color;

const vec2 corners[6] = vec2[](vec2(0, -1), vec2(1, -1), vec2(1, 1), vec2(0, -1), vec2(1, 1),
                               vec2(0, 1));

vec4 project(vec3 p) {
  if (pc.space == 1u) return u.panelProj * vec4(p, 1.0);
  p += (u.eye[VIEW].xyz - p) * pc.towardEye;
  vec4 clip = u.viewProj[VIEW] * vec4(p, 1.0);
  clip.w = max(clip.w, 1e-6);  // a segment through the eye degenerates instead of flipping
  return clip;
}

void main() {
  vec4 a = project(inA);
  vec4 b = project(inB);
  vec2 corner = corners[gl_VertexIndex];
  vec2 halfSize = 0.5 * pc.viewportSize;
  vec2 sa = a.xy / a.w * halfSize;
  vec2 sb = b.xy / b.w * halfSize;
  vec2 along = sb - sa;
  along = dot(along, along) > 1e-12 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  float halfWidth = 0.5 * pc.widthPixels;
  vec4 clip = corner.x == 0.0 ? a : b;
  vec2 offset = across * corner.y * halfWidth + along * (corner.x == 0.0 ? -halfWidth : halfWidth);
  clip.xy += offset / halfSize * clip.w;
  gl_Position = clip;
  color = inColor;
}
