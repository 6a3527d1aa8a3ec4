// The subsurface LPV's light leaving a translucent surface (thesis 5.4, step 4), shared by
// shaders/subsurface/render.comp and its CPU kernel (variants/rendering/subsurface_cpu.h): the
// accumulated SSLPV, trilinearly interpolated between the 8 nearest cell centres (clamped at the
// grid's edge) at the surface point, projected on the light leaving through the surface,
// L_o = <I, cosLobe(n)> / (pi s^2) (subsurface.glsl).
// The including kernel defines, before including this:
//   SH_COEFFICIENTS (the grid's coefficients per channel) and
//   real subsurfaceGridValue(int channel, int k, int cell, int cells): the accumulated grid's
//   coefficient k of `channel` in `cell` (grid.glsl's layout over `cells` cells).
#ifndef LPVLAB_SUBSURFACE_EXIT_GLSL
#define LPVLAB_SUBSURFACE_EXIT_GLSL
#include "../common/sh.glsl"
#include "../common/grid.glsl"
#include "../rendering/trilinear_weights.glsl"
#include "subsurface.glsl"

// The radiance (W/(m^2 sr), per channel) leaving the translucent surface at world `position`
// with outward unit normal n.
vec3 subsurfaceExitingRadiance(vec3 position, vec3 n, vec3 gridOrigin, real cellSize,
                               ivec3 resolution) {
  real lobe[SH_MAX_COEFFICIENTS];
  for (int k = 0; k < SH_COEFFICIENTS; ++k) lobe[k] = subsurfaceExitLobeAt(k, n);
  // Cell centres sit at integer + 0.5 in grid coordinates.
  vec3 centred = gridFromWorld(position, gridOrigin, cellSize) - real(0.5);
  vec3 base = floor(centred);
  vec3 f = centred - base;
  int cells = cellCount(resolution);
  vec3 projected = vec3(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    int index = cellIndex(clamp(ivec3(base) + o, ivec3(0), resolution - 1), resolution);
    for (int channel = 0; channel < 3; ++channel) {
      real v = real(0.0);
      for (int k = 0; k < SH_COEFFICIENTS; ++k)
        v += subsurfaceGridValue(channel, k, index, cells) * lobe[k];
      projected[channel] += trilinearWeight(o, f) * v;
    }
  }
  return vec3(subsurfaceExitRadiance(projected.x, cellSize),
              subsurfaceExitRadiance(projected.y, cellSize),
              subsurfaceExitRadiance(projected.z, cellSize));
}

#endif
