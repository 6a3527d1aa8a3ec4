// The subsurface LPV's per-pixel mathematics (thesis 5.4), shared by shaders/subsurface/render.comp
// and the double-precision C++ tests.
//
// The SSLPV holds radiant intensity I (W/sr) per cell, like the light grid; spread over the cell's
// cross-section it is the radiance L = I / s^2 (s: cell size). At a translucent surface with
// outward unit normal n, the light inside travelling out through it has the exitance
//     M = integral L(w) max(0, n . w) dw = <I, cosLobe(n)> / s^2                     [W/m^2]
// (the cosine lobe about +n: the light leaves, where the light grid's rendering takes the lobe
// about -n for light arriving). The surface lets all of it out, diffusely (a rough interface
// with no internal reflection: the entering side carries the material's transmittance), so the
// radiance leaving it towards any viewer is
//     L_o = M / pi = <I, cosLobe(n)> / (pi s^2).
#ifndef LPVLAB_SUBSURFACE_GLSL
#define LPVLAB_SUBSURFACE_GLSL
#include "../common/sh.glsl"

// Coefficient k of the lobe that projects the SSLPV's intensity on the light leaving through a
// surface with outward normal n.
real subsurfaceExitLobeAt(int k, vec3 n) {
  return shCosineLobeAt(k, n);
}

// L_o (W/(m^2 sr)) from the projected intensity <I, cosLobe(n)> (W/sr times sr); negative
// projections (SH ringing) give nothing.
real subsurfaceExitRadiance(real projectedIntensity, real cellSize) {
  return max(projectedIntensity, real(0.0)) / (PI * cellSize * cellSize);
}

#endif
