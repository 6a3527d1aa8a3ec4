// One shadow-map tap as GL defines LINEAR filtering with a LEQUAL depth comparison (OpenGL 4.6,
// 8.14.2 and 8.23.1), written out for a backend without a texture unit (the CPU kernel of
// direct_light.glsl): the four texels around window position uv (texel centres at integer + 0.5,
// clamped to the map's edge) are compared with `reference`, 1 where reference <= the stored
// depth, and the results are weighted bilinearly. (The shadow maps are DEPTH32F, a floating-point
// format, so neither depth is clamped to [0, 1].) The GL kernel asks its texture unit, which
// computes the same; tests/pipeline/direct_lighting_test.cpp compares the two.
// Shared subset; the includer defines
//   real shadowDepth(int view, ivec2 texel)  the depth stored at texel (inside the map)
#ifndef LPVLAB_SHADOW_TAP_GLSL
#define LPVLAB_SHADOW_TAP_GLSL
#include "../common/prelude.glsl"

real shadowTexelLit(int view, ivec2 texel, real reference, int resolution) {
  ivec2 c = clamp(texel, ivec2(0), ivec2(resolution - 1));
  return reference <= shadowDepth(view, c) ? real(1.0) : real(0.0);
}

real shadowTapBilinear(int view, vec2 uv, real reference, int resolution) {
  vec2 t = uv * real(resolution) - real(0.5);
  vec2 b = floor(t);
  vec2 f = t - b;
  ivec2 i = ivec2(b);
  real s00 = shadowTexelLit(view, i, reference, resolution);
  real s10 = shadowTexelLit(view, i + ivec2(1, 0), reference, resolution);
  real s01 = shadowTexelLit(view, i + ivec2(0, 1), reference, resolution);
  real s11 = shadowTexelLit(view, i + ivec2(1, 1), reference, resolution);
  return mix(mix(s00, s10, f.x), mix(s01, s11, f.x), f.y);
}

#endif
