// The colour written to the render target. Colours are chosen as sRGB-encoded values (what a
// UNORM target shows as is); an sRGB target encodes what it is given, so it is given their linear
// value and shows the same colour (OpenXR compositors expect sRGB swapchains to hold linear light).
// Set per pipeline from the target's format (scene_renderer.cpp).
layout(constant_id = 0) const bool kSrgbTarget = false;

vec3 linearFromSrgb(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

vec4 targetColor(vec4 c) {
  return kSrgbTarget ? vec4(linearFromSrgb(clamp(c.rgb, 0.0, 1.0)), c.a) : c;
}
