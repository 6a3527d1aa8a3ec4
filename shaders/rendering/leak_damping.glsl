// Leak damping (thesis 4.5, Kaplanyan and Dachsbacher 2010, sec. "light bleeding"): light that
// reached a surface's front through a thin wall behind it is brightest at the wall and fades
// away from it, while light that really arrives from the front grows, or stays, towards its
// source. So the irradiance read E(t) = <c(x + t n), cosLobe(-n)>, moved t cells along the
// surface normal n, falls with t where the light leaked: its relative growth towards the surface
//   g = max(0, -(dE/dt) / E)            (per cell; 0 where E <= 0)
// measures how strongly, and the read is damped by
//   D = exp(-strength * g),
// which is 1 where the light is uniform or comes from the front (g = 0), falls smoothly with g,
// and never makes the light negative. E and dE/dt are sums over the colour channels, so one
// factor scales all three and damping does not change the light's colour.
#ifndef LPVLAB_LEAK_DAMPING_GLSL
#define LPVLAB_LEAK_DAMPING_GLSL
#include "../common/prelude.glsl"

// E's relative growth towards the surface per cell, from E and its slope along the normal.
real leakGrowth(real irradiance, real slopeAlongNormal) {
  if (irradiance <= real(0.0) || slopeAlongNormal >= real(0.0)) return real(0.0);
  return -slopeAlongNormal / irradiance;
}

real leakDampingFactor(real irradiance, real slopeAlongNormal, real strength) {
  return exp(-strength * leakGrowth(irradiance, slopeAlongNormal));
}

#endif
