// Per-frame values; must match FrameUniforms in engine/render/scene_renderer.cpp. Two views: a
// multiview pass (VK_KHR_multiview: both eyes in one pass, each draw seen from both) picks its own
// with gl_ViewIndex; an ordinary pass uses view 0. Included first, before any declaration.
#ifdef CURVEFOLD_MULTIVIEW
#extension GL_EXT_multiview : require
#define VIEW gl_ViewIndex
#else
#define VIEW 0
#endif

layout(set = 0, binding = 0) uniform Frame {
  mat4 viewProj[2];
  mat4 view[2];
  mat4 proj[2];
  mat4 model;      // world_from_sheet
  mat4 panelProj;  // development -> panel clip space
  vec4 eye[2];     // world
  vec4 lightDir;   // world, towards the light; w = ambient
  vec4 frontColor;
  vec4 backColor;
  vec4 tintColor;  // rgb; a = how much of it the reflected part takes
  vec4 viewport;   // width, height in pixels
} u;
