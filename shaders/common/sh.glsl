// Real spherical harmonics up to order 3 (bands l = 0..3; order L has (L + 1)^2 coefficients per
// colour channel), thesis eq. 4.2 and 4.3 for order 1. Coefficient index i = l (l + 1) + m, so
// order 1 is (c0, c1, c2, c3) = (Y00, Y1-1, Y10, Y11).
//
// A function f on the sphere is represented by c_i = integral f(w) Y_i(w) dw, and evaluated as
// f(w) ~ sum c_i Y_i(w). In lpvlab the light grid stores radiant intensity I(w) in W/sr of the
// light travelling in direction w.
//
// The basis is the usual real one with the Condon-Shortley phase (odd m negative), which gives
// eq. 4.2's signs; each band is orthonormal, which is all the addition theorem needs:
// sum_m Y_lm(a) Y_lm(b) = (2l + 1) / (4 pi) P_l(a . b). Orthonormality, the lobes and rotation
// invariance are checked by numerical integration in tests/math/sh_test.cpp.
//
// Order-generic kernels hold coefficients in local arrays and call the scalar functions below
// with a loop bound that is a specialisation constant, so the basis constant-folds; the vec4
// functions are the order-1 convenience the shared C++ and order-1 code use.
#ifndef LPVLAB_SH_GLSL
#define LPVLAB_SH_GLSL
#include "prelude.glsl"

const int SH_MAX_ORDER = 3;
const int SH_MAX_COEFFICIENTS = 16;

const real SH_Y0 = 0.5 / sqrt(PI);
const real SH_Y1 = 0.5 * sqrt(3.0 / PI);

int shCoefficientCount(int order) {
  return (order + 1) * (order + 1);
}

// The band l of coefficient i = l (l + 1) + m.
int shBand(int i) {
  return i < 1 ? 0 : (i < 4 ? 1 : (i < 9 ? 2 : 3));
}

// Y_i(w) for unit w, i < 16.
real shBasisAt(int i, vec3 w) {
  real x = w.x;
  real y = w.y;
  real z = w.z;
  switch (i) {
    case 0: return SH_Y0;
    case 1: return -SH_Y1 * y;
    case 2: return SH_Y1 * z;
    case 3: return -SH_Y1 * x;
    case 4: return 0.5 * sqrt(15.0 / PI) * x * y;
    case 5: return -0.5 * sqrt(15.0 / PI) * y * z;
    case 6: return 0.25 * sqrt(5.0 / PI) * (3.0 * z * z - 1.0);
    case 7: return -0.5 * sqrt(15.0 / PI) * x * z;
    case 8: return 0.25 * sqrt(15.0 / PI) * (x * x - y * y);
    case 9: return -0.25 * sqrt(35.0 / (2.0 * PI)) * y * (3.0 * x * x - y * y);
    case 10: return 0.5 * sqrt(105.0 / PI) * x * y * z;
    case 11: return -0.25 * sqrt(21.0 / (2.0 * PI)) * y * (5.0 * z * z - 1.0);
    case 12: return 0.25 * sqrt(7.0 / PI) * z * (5.0 * z * z - 3.0);
    case 13: return -0.25 * sqrt(21.0 / (2.0 * PI)) * x * (5.0 * z * z - 1.0);
    case 14: return 0.25 * sqrt(105.0 / PI) * z * (x * x - y * y);
    case 15: return -0.25 * sqrt(35.0 / (2.0 * PI)) * x * (x * x - 3.0 * y * y);
  }
  return 0.0;
}

// Zonal coefficients of the clamped cosine lobe max(0, cos theta) about z,
// z_l = 2 pi integral_0^1 Y_l0(t) t dt: z_0 = sqrt(pi) / 2, z_1 = sqrt(pi / 3),
// z_2 = sqrt(5 pi) / 8, z_3 = 0 (odd bands above 1 vanish).
real shZonalCosine(int band) {
  switch (band) {
    case 0: return 0.5 * sqrt(PI);
    case 1: return sqrt(PI / 3.0);
    case 2: return sqrt(5.0 * PI) / 8.0;
  }
  return 0.0;
}

// Coefficient i of max(0, n . w) (n unit): the zonal lobe rotated to n, which multiplies each
// band by sqrt(4 pi / (2l + 1)) Y_lm(n) (eq. 4.3 for order 1).
real shCosineLobeAt(int i, vec3 n) {
  int band = shBand(i);
  return shZonalCosine(band) * sqrt(4.0 * PI / real(2 * band + 1)) * shBasisAt(i, n);
}

vec4 shBasis(vec3 w) {
  return vec4(shBasisAt(0, w), shBasisAt(1, w), shBasisAt(2, w), shBasisAt(3, w));
}

// max(0, dot(n, w)) projected onto the order-1 basis; n must be unit length.
vec4 shCosineLobe(vec3 n) {
  return vec4(shCosineLobeAt(0, n), shCosineLobeAt(1, n), shCosineLobeAt(2, n), shCosineLobeAt(3, n));
}

real shEvaluate(vec4 c, vec3 w) {
  return dot(c, shBasis(w));
}

// Integral of the represented function over the sphere (any order): only Y00 has a non-zero
// integral, integral Y00 dw = 4 pi * Y00 = 2 sqrt(pi). For an intensity this is the flux in W.
real shIntegralOfC0(real c0) {
  return c0 * 2.0 * sqrt(PI);
}

real shIntegral(vec4 c) {
  return shIntegralOfC0(c.x);
}

#endif
