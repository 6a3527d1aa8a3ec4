// Light emission shared by the LPV pipeline and the reference path tracer, so both model a light
// identically. Units: spot and point lights give radiant intensity (W/sr); the result of
// spotFalloff multiplies it.
#ifndef LPVLAB_LIGHTS_GLSL
#define LPVLAB_LIGHTS_GLSL
#include "prelude.glsl"

// glTF KHR_lights_punctual spot cone: smooth from 1 inside the inner half-angle to 0 at the
// outer one, attenuation = clamp((cos(angle) - cos(outer)) / (cos(inner) - cos(outer)), 0, 1)^2.
// `cosAngle` is dot(spot direction, direction from the light to the point).
real spotFalloff(real cosAngle, real cosInner, real cosOuter) {
  real scale = real(1.0) / max(real(0.001), cosInner - cosOuter);
  real t = clamp((cosAngle - cosOuter) * scale, real(0.0), real(1.0));
  return t * t;
}

#endif
