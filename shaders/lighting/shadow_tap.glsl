// Shadow-map taps as GL defines LINEAR filtering with a LEQUAL depth comparison (OpenGL 4.6,
// 8.14.2 and 8.23.1), written out for a backend without a texture unit (the CPU kernel of
// direct_light.glsl). One tap compares the four texels around window position uv (texel centres
// at integer + 0.5, clamped to the map's edge) with `reference`, 1 where reference <= the stored
// depth, and weights the results bilinearly by uv's fraction f. (The shadow maps are DEPTH32F, a
// floating-point format, so neither depth is clamped to [0, 1].)
//
// Nine such taps one texel apart, as direct light takes them, share their fractions and overlap:
// along each axis the taps at -1, 0, +1 weight the texels i-1 .. i+2 of the centre tap's i by
// (1 - f, 1, 1, f). So the nine taps' mean is one pass over 4x4 texels with those separable
// weights, over 9: 16 comparisons instead of 36, the same value up to rounding. The GL kernel asks
// its texture unit tap by tap; tests/pipeline/direct_lighting_test.cpp compares the two.
// Shared subset; the includer defines
//   real shadowDepth(int view, ivec2 texel)  the depth stored at texel (inside the map)
#ifndef LPVLAB_SHADOW_TAP_GLSL
#define LPVLAB_SHADOW_TAP_GLSL
#include "../common/prelude.glsl"

real shadowTexelLit(int view, ivec2 texel, real reference, int resolution) {
  ivec2 c = clamp(texel, ivec2(0), ivec2(resolution - 1));
  return reference <= shadowDepth(view, c) ? real(1.0) : real(0.0);
}

// The weight of texel a (0..3, i.e. i-1 .. i+2) in the nine taps along one axis, fraction f.
real shadowTapsWeight(int a, real f) {
  if (a == 0) return real(1.0) - f;
  if (a == 3) return f;
  return real(1.0);
}

real shadowTaps3x3Bilinear(int view, vec2 uv, real reference, int resolution) {
  vec2 t = uv * real(resolution) - real(0.5);
  vec2 b = floor(t);
  vec2 f = t - b;
  ivec2 i = ivec2(b) - ivec2(1);
  real lit = 0.0;
  for (int y = 0; y < 4; ++y) {
    real row = 0.0;
    for (int x = 0; x < 4; ++x)
      row += shadowTapsWeight(x, f.x) * shadowTexelLit(view, i + ivec2(x, y), reference, resolution);
    lit += shadowTapsWeight(y, f.y) * row;
  }
  return lit / real(9.0);
}

#endif
