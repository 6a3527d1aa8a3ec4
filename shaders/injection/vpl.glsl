// A reflective-shadow-map texel as a virtual point light (thesis eq. 4.1-4.3), in the shared
// GLSL/C++ subset (prelude.glsl): the GL injection kernel (rsm_vpl.comp) and the CPU one
// (variants/injection/rsm_vpl_cpu.cpp) both call these. A Lambertian VPL of flux Phi and unit
// normal n has intensity I(w) = Phi / pi * max(0, n . w), whose SH coefficients are
// Phi * vplLobeAt(k, n); it is injected into the cell containing its position moved `shiftCells`
// cells along n (against self-illumination).
#ifndef LPVLAB_VPL_GLSL
#define LPVLAB_VPL_GLSL
#include "../common/prelude.glsl"
#include "../common/sh.glsl"
#include "../common/grid.glsl"

ivec3 vplCell(vec3 position, vec3 n, vec3 gridOrigin, real cellSize, real shiftCells) {
  vec3 p = position + n * (shiftCells * cellSize);
  return surfaceCell(gridFromWorld(p, gridOrigin, cellSize), n);
}

// Coefficient k of the intensity of a VPL of unit flux with normal n: cosLobe(n) / pi.
real vplLobeAt(int k, vec3 n) {
  return shCosineLobeAt(k, n) / PI;
}

#endif
