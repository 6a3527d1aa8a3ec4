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

// One row of the 4x4 texels: columns (clamped to the map), their weights wx; 1 where
// reference <= the stored depth.
real shadowRowLit(int view, ivec4 columns, int row, real reference, vec4 wx) {
  vec4 depth = vec4(shadowDepth(view, ivec2(columns.x, row)), shadowDepth(view, ivec2(columns.y, row)),
                    shadowDepth(view, ivec2(columns.z, row)), shadowDepth(view, ivec2(columns.w, row)));
  return dot(wx, step(vec4(reference), depth));
}

real shadowTaps3x3Bilinear(int view, vec2 uv, real reference, int resolution) {
  vec2 t = uv * real(resolution) - real(0.5);
  vec2 b = floor(t);
  vec2 f = t - b;
  // The texels i-1 .. i+2 along each axis, clamped to the map's edge once per axis, and their
  // weights (1 - f, 1, 1, f).
  ivec4 last = ivec4(resolution - 1);
  ivec4 columns = clamp(ivec4(int(b.x)) + ivec4(-1, 0, 1, 2), ivec4(0), last);
  ivec4 rows = clamp(ivec4(int(b.y)) + ivec4(-1, 0, 1, 2), ivec4(0), last);
  vec4 wx = vec4(real(1.0) - f.x, real(1.0), real(1.0), f.x);
  vec4 wy = vec4(real(1.0) - f.y, real(1.0), real(1.0), f.y);
  vec4 lit = vec4(shadowRowLit(view, columns, rows.x, reference, wx),
                  shadowRowLit(view, columns, rows.y, reference, wx),
                  shadowRowLit(view, columns, rows.z, reference, wx),
                  shadowRowLit(view, columns, rows.w, reference, wx));
  return dot(wy, lit) / real(9.0);
}

#endif
