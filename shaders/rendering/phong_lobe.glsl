// The normalised Phong lobe P(w) = (m + 1) / (2 pi) max(0, w . a)^m about a unit axis a, exponent
// m >= 1, in SH (any order up to 3), for glossy reflections read from the light grid. P
// integrates to 1 over the sphere, so <c, P> = integral f(w) P(w) dw is the lobe-weighted mean of
// the function f that c represents: a constant f gives that constant whatever m and a.
//
// P is zonal about a, so (as for the cosine lobe in sh.glsl) its coefficient i in band l is
//   Lambda_l(m) Y_i(a),  Lambda_l = sqrt(4 pi / (2l + 1)) 2 pi integral_0^1 Y_l0(t) P(t) dt,
// which with Y_l0 as polynomials in t = cos theta gives
//   Lambda_0 = 1,  Lambda_1 = (m + 1) / (m + 2),  Lambda_2 = m / (m + 3),
//   Lambda_3 = (m + 1)(m - 1) / ((m + 2)(m + 4)).
// m = 1 is the normalised clamped cosine (1, 2/3, 1/4, 0); m -> infinity tends to evaluation at a
// (all Lambda_l -> 1). Checked by numerical integration in tests/variants/rendering/rendering_variants_test.cpp.
#ifndef LPVLAB_PHONG_LOBE_GLSL
#define LPVLAB_PHONG_LOBE_GLSL
#include "../common/sh.glsl"

real phongLobeBandScale(int band, real m) {
  switch (band) {
    case 0: return real(1.0);
    case 1: return (m + real(1.0)) / (m + real(2.0));
    case 2: return m / (m + real(3.0));
    case 3: return (m + real(1.0)) * (m - real(1.0)) / ((m + real(2.0)) * (m + real(4.0)));
  }
  return real(0.0);
}

// Coefficient i of the normalised Phong lobe of exponent m about the unit axis a.
real shPhongLobeAt(int i, vec3 a, real m) {
  return phongLobeBandScale(shBand(i), m) * shBasisAt(i, a);
}

#endif
