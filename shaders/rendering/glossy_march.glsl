// "glossy" rendering's reflection (docs/variants/glossy.md#glossy), in the shared GLSL/C++ subset
// (prelude.glsl): the GL kernel (trilinear.comp) and the CPU kernel (trilinear_cpu.cpp) call
// these same functions. The includer defines, besides trilinear_diffuse.glsl's gridCoefficient
// (the level being rendered), cascade_weight.glsl's cascadeLevelOrigin and cascadeLevelCellSize.
#ifndef LPVLAB_GLOSSY_MARCH_GLSL
#define LPVLAB_GLOSSY_MARCH_GLSL
#include "../common/cascade_weight.glsl"
#include "phong_lobe.glsl"
#include "trilinear_diffuse.glsl"

// How the march is set: the Phong exponent, the step in cells of the coarsest level, the
// number of samples, and the cascade levels (the one rendered, how many, their resolution and
// blend band).
struct GlossyMarch {
  real phongExponent;
  real stepCells;
  int samples;
  int current;
  int levels;
  ivec3 resolution;
  real blendCells;
};

// Mean lobe-weighted intensity (W/sr) arriving at p from around the reflected direction r, read
// at march.samples points p + (j + 1/2) step r, in cells of the coarsest level (the only level
// without cascades), each from the rendered level's grid (origin, cell size, `coefficients` per
// channel) weighted by that level's cascade weight there. The march ends where it leaves the
// coarsest level, but always reads its first sample (clamped to the grid's edge, as the diffuse
// read is), so a surface next to the edge still gets a glossy term.
vec3 glossyIntensity(vec3 p, vec3 r, GlossyMarch march, vec3 gridOrigin, real cellSize,
                     int coefficients) {
  real lobe[SH_MAX_COEFFICIENTS];
  // Light arriving from r travels along -r.
  for (int k = 0; k < coefficients; ++k) lobe[k] = shPhongLobeAt(k, -r, march.phongExponent);
  int coarsest = march.levels - 1;
  real step = march.stepCells * cascadeLevelCellSize(coarsest);
  vec3 sum = vec3(0.0);
  int inside = 0;
  for (int j = 0; j < march.samples; ++j) {
    vec3 x = p + r * ((real(j) + real(0.5)) * step);
    vec3 g = cascadeGridCoordinates(x, coarsest);
    if (j > 0 && (any(lessThan(g, vec3(0.0))) || any(greaterThan(g, vec3(march.resolution)))))
      break;
    real weight = cascadeLevelWeight(x, march.current, march.levels, march.resolution,
                                     march.blendCells);
    if (weight > real(0.0))
      sum += weight * sampleLobe(gridFromWorld(x, gridOrigin, cellSize), lobe, coefficients,
                                 march.resolution, false, r).value;
    ++inside;
  }
  return inside > 0 ? max(sum / real(inside), vec3(0.0)) : vec3(0.0);
}

// The glossy radiance (W/(m^2 sr)) at a surface point (unit normal n) seen from cameraPosition:
// specularAlbedo times the grid's intensity marched along the reflected view direction from the
// point moved normalOffsetCells cells along n, as radiance I / cellSize^2.
vec3 glossyRadiance(vec3 position, vec3 n, vec3 cameraPosition, real specularAlbedo,
                    real normalOffsetCells, GlossyMarch march, vec3 gridOrigin, real cellSize,
                    int coefficients) {
  vec3 p = position + n * (normalOffsetCells * cellSize);
  vec3 toCamera = cameraPosition - position;
  vec3 v = dot(toCamera, toCamera) > real(0.0) ? normalize(toCamera) : n;
  return specularAlbedo *
         glossyIntensity(p, reflect(-v, n), march, gridOrigin, cellSize, coefficients) /
         (cellSize * cellSize);
}

#endif
