// Real spherical harmonics of order 1 (bands l = 0 and 1: four coefficients per colour channel),
// thesis eq. 4.2 and 4.3. Coefficient order (c0, c1, c2, c3) = (Y00, Y1-1, Y10, Y11).
//
// A function f on the sphere is represented by c_i = integral f(w) Y_i(w) dw, and evaluated as
// f(w) ~ sum c_i Y_i(w). In lpvlab the light grid stores radiant intensity I(w) in W/sr of the
// light travelling in direction w.
#ifndef LPVLAB_SH_GLSL
#define LPVLAB_SH_GLSL
#include "prelude.glsl"

// Y00 = 1 / (2 sqrt(pi)); Y1m = sqrt(3) / (2 sqrt(pi)) * (-y, z, -x).
const real SH_Y0 = 0.5 / sqrt(PI);
const real SH_Y1 = 0.5 * sqrt(3.0 / PI);

// Zonal coefficients of the clamped cosine lobe max(0, cos theta), z_l = 2 pi integral_0^1
// Y_l0(t) t dt: z_0 = sqrt(pi) / 2, z_1 = sqrt(pi / 3). Rotated to axis n they are multiplied by
// sqrt(4 pi / (2l + 1)) Y_lm(n), which gives eq. 4.3.
const real SH_COSINE_Z0 = 0.5 * sqrt(PI);
const real SH_COSINE_Z1 = sqrt(PI / 3.0);

vec4 shBasis(vec3 w) {
  return vec4(SH_Y0, -SH_Y1 * w.y, SH_Y1 * w.z, -SH_Y1 * w.x);
}

// max(0, dot(n, w)) projected onto the basis; n must be unit length.
vec4 shCosineLobe(vec3 n) {
  return vec4(SH_COSINE_Z0, -SH_COSINE_Z1 * n.y, SH_COSINE_Z1 * n.z, -SH_COSINE_Z1 * n.x);
}

real shEvaluate(vec4 c, vec3 w) {
  return dot(c, shBasis(w));
}

// Integral of the represented function over the sphere: only Y00 has a non-zero integral,
// integral Y00 dw = 4 pi * Y00 = 2 sqrt(pi). For an intensity this is the total flux in W.
real shIntegral(vec4 c) {
  return c.x * 2.0 * sqrt(PI);
}

#endif
