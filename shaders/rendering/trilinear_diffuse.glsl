// The diffuse indirect light of "trilinear" rendering at one surface point, in the shared
// GLSL/C++ subset (prelude.glsl): the GL kernel (trilinear.comp) and the CPU kernel
// (variants/rendering/trilinear_cpu.cpp) both call these functions, so the two backends shade
// with the same text. The includer defines how the accumulated light grid is read:
//   real gridCoefficient(int channel, int k, int coefficients, int cell, int cells)
// the coefficient k of a channel of a cell: in GLSL from the storage buffer (grid.glsl layout),
// in C++ from a copy laid out cell by cell, which a CPU's caches prefer.
//
// The grid holds intensity I (W/sr) per cell; spread over the cell's cross-section it is the
// radiance L = I / cellSize^2 (Kaplanyan and Dachsbacher 2010). The irradiance from the light
// arriving at a surface with normal n is E = integral L(w) max(0, -n . w) dw = <L, cosLobe(-n)>,
// and the Lambertian surface reflects L_o = albedo / pi * E. With leak damping, E is scaled by
// leak_damping.glsl's factor, from E's slope along n, which the same 8 reads give
// (trilinear_weights.glsl).
#ifndef LPVLAB_TRILINEAR_DIFFUSE_GLSL
#define LPVLAB_TRILINEAR_DIFFUSE_GLSL
#include "../common/prelude.glsl"
#include "../common/sh.glsl"
#include "../common/grid.glsl"
#include "trilinear_weights.glsl"
#include "leak_damping.glsl"

// The grid's intensity projected on `lobe` (its first `coefficients` entries), per channel,
// trilinearly interpolated at grid coordinates g between the 8 nearest cell centres (clamped at
// the grid's edge), and, if withSlope, its derivative per cell along the unit direction d.
struct LobeSample {
  vec3 value;
  vec3 slope;
};

LobeSample sampleLobe(vec3 g, real lobe[SH_MAX_COEFFICIENTS], int coefficients, ivec3 resolution,
                      bool withSlope, vec3 d) {
  // Cell centres sit at integer + 0.5 in grid coordinates.
  vec3 centred = g - real(0.5);
  vec3 base = floor(centred);
  vec3 f = centred - base;
  int cells = cellCount(resolution);
  // The projection on the lobe is linear, so the 8 cells' coefficients are interpolated first and
  // projected once: per corner one multiply-add per coefficient and channel (runs of N floats a
  // CPU does as short vectors), no sum over the coefficients until the end. The channels by name,
  // not v[channel]: GLM's run-time component index is a branch.
  real red[SH_MAX_COEFFICIENTS];
  real green[SH_MAX_COEFFICIENTS];
  real blue[SH_MAX_COEFFICIENTS];
  real redSlope[SH_MAX_COEFFICIENTS];
  real greenSlope[SH_MAX_COEFFICIENTS];
  real blueSlope[SH_MAX_COEFFICIENTS];
  for (int k = 0; k < coefficients; ++k) {
    red[k] = real(0.0);
    green[k] = real(0.0);
    blue[k] = real(0.0);
    redSlope[k] = real(0.0);
    greenSlope[k] = real(0.0);
    blueSlope[k] = real(0.0);
  }
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    int index = cellIndex(clamp(ivec3(base) + o, ivec3(0), resolution - 1), resolution);
    real w = trilinearWeight(o, f);
    for (int k = 0; k < coefficients; ++k) {
      red[k] += w * gridCoefficient(0, k, coefficients, index, cells);
      green[k] += w * gridCoefficient(1, k, coefficients, index, cells);
      blue[k] += w * gridCoefficient(2, k, coefficients, index, cells);
    }
    if (withSlope) {
      real ws = trilinearWeightSlope(o, f, d);
      for (int k = 0; k < coefficients; ++k) {
        redSlope[k] += ws * gridCoefficient(0, k, coefficients, index, cells);
        greenSlope[k] += ws * gridCoefficient(1, k, coefficients, index, cells);
        blueSlope[k] += ws * gridCoefficient(2, k, coefficients, index, cells);
      }
    }
  }
  LobeSample s;  // member by member (shared.h: no struct constructors)
  s.value = vec3(0.0);
  s.slope = vec3(0.0);
  for (int k = 0; k < coefficients; ++k) {
    s.value += lobe[k] * vec3(red[k], green[k], blue[k]);
    s.slope += lobe[k] * vec3(redSlope[k], greenSlope[k], blueSlope[k]);
  }
  return s;
}

// The radiance (W/(m^2 sr)) a Lambertian surface of `albedo` at `position` with unit normal n
// reflects of the grid's light, read `normalOffsetCells` cells along n; leakDamping > 0 damps it
// (leak_damping.glsl). The grid: origin, cell size (m), resolution, SH coefficients per channel.
vec3 trilinearDiffuse(vec3 position, vec3 n, vec3 albedo, vec3 gridOrigin, real cellSize,
                      ivec3 resolution, int coefficients, real normalOffsetCells,
                      real leakDamping) {
  vec3 p = position + n * (normalOffsetCells * cellSize);
  real lobe[SH_MAX_COEFFICIENTS];
  for (int k = 0; k < coefficients; ++k) lobe[k] = shCosineLobeAt(k, -n);
  bool damped = leakDamping > real(0.0);
  LobeSample diffuse =
      sampleLobe(gridFromWorld(p, gridOrigin, cellSize), lobe, coefficients, resolution, damped, n);
  vec3 e = diffuse.value;
  if (damped)
    e *= leakDampingFactor(e.x + e.y + e.z, diffuse.slope.x + diffuse.slope.y + diffuse.slope.z,
                           leakDamping);
  return albedo / PI * max(e, vec3(0.0)) / (cellSize * cellSize);
}

#endif
