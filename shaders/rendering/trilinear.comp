#version 450
// Indirect light at every G-buffer pixel from the accumulated light grid, trilinearly
// interpolated between the 8 nearest cell centres (clamped at the grid's edge), at any SH order.
// One dispatch per cascade level: each adds its light times the level's weight
// (cascade_blend.glsl) to the output, which the pipeline zeroed.
// The grid holds intensity I (W/sr) per cell; spread over the cell's cross-section it is the
// radiance L = I / cellSize^2 (Kaplanyan and Dachsbacher 2010). The irradiance from the light
// arriving at a surface with normal n is E = integral L(w) max(0, -n . w) dw = <L, cosLobe(-n)>,
// and the Lambertian surface reflects L_o = albedo / pi * E.
// Options (specialisation constants, so "trilinear" alone pays for neither):
//   LEAK_DAMPING: E is scaled by leak_damping.glsl's factor, from E's slope along n, which the
//                 same 8 reads give (trilinear_weights.glsl).
//   GLOSSY:       adds specularAlbedo * the grid's radiance arriving from the reflected view
//                 direction r, weighted by a normalised Phong lobe (phong_lobe.glsl) and averaged
//                 over samples marched along r (docs/variants.md#glossy).
#include "../common/sh.glsl"
#include "../common/grid.glsl"
#include "../common/cascade_blend.glsl"
#include "trilinear_weights.glsl"
#include "leak_damping.glsl"
#include "phong_lobe.glsl"

#include "trilinear_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;
layout(constant_id = 1) const bool LEAK_DAMPING = false;
layout(constant_id = 2) const bool GLOSSY = false;

layout(binding = UNIT_G_POSITION) uniform sampler2D gPosition;
layout(binding = UNIT_G_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_G_ALBEDO) uniform sampler2D gAlbedo;
layout(std430, binding = BUFFER_ACCUMULATED) readonly buffer Accumulated { float grid[]; };
layout(binding = IMAGE_OUT_INDIRECT, rgba32f) uniform image2D outIndirect;

layout(location = LOCATION_GRID_ORIGIN) uniform vec3 gridOrigin;
layout(location = LOCATION_CELL_SIZE) uniform float cellSize;
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_NORMAL_OFFSET_CELLS) uniform float normalOffsetCells;
layout(location = LOCATION_LEAK_DAMPING_STRENGTH) uniform float leakDampingStrength;
layout(location = LOCATION_CAMERA_POSITION) uniform vec3 cameraPosition;
layout(location = LOCATION_SPECULAR_ALBEDO) uniform float specularAlbedo;
layout(location = LOCATION_PHONG_EXPONENT) uniform float phongExponent;
layout(location = LOCATION_MARCH_STEP_CELLS) uniform float marchStepCells;
layout(location = LOCATION_MARCH_SAMPLES) uniform int marchSamples;
layout(location = LOCATION_INDIRECT_SCALE) uniform float indirectScale;  // [rendering] scale

// The grid's intensity projected on `lobe`, per channel, trilinearly interpolated at grid
// coordinates g, and (if withSlope) its derivative per cell along the unit direction d.
struct LobeSample {
  vec3 value;
  vec3 slope;
};

LobeSample sampleLobe(vec3 g, float lobe[SH_MAX_COEFFICIENTS], bool withSlope, vec3 d) {
  // Cell centres sit at integer + 0.5 in grid coordinates.
  vec3 centred = g - 0.5;
  vec3 base = floor(centred);
  vec3 f = centred - base;
  int cells = cellCount(resolution);
  LobeSample s = LobeSample(vec3(0.0), vec3(0.0));
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    int index = cellIndex(clamp(ivec3(base) + o, ivec3(0), resolution - 1), resolution);
    vec3 v = vec3(0.0);
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < SH_COEFFICIENTS; ++k)
        v[channel] += grid[coefficientIndex(channel, k, SH_COEFFICIENTS, index, cells)] * lobe[k];
    s.value += trilinearWeight(o, f) * v;
    if (withSlope) s.slope += trilinearWeightSlope(o, f, d) * v;
  }
  return s;
}

// Mean lobe-weighted intensity (W/sr) arriving at p from around the reflected direction r, read
// at marchSamples points p + (j + 1/2) marchStepCells r, in cells of the coarsest level (the only
// level without cascades), each weighted by this level's cascade weight there. The march ends
// where it leaves the coarsest level, but always reads its first sample (clamped to the grid's
// edge, as the diffuse read is), so a surface next to the edge still gets a glossy term.
vec3 glossyIntensity(vec3 p, vec3 r) {
  float lobe[SH_MAX_COEFFICIENTS];
  // Light arriving from r travels along -r.
  for (int k = 0; k < SH_COEFFICIENTS; ++k) lobe[k] = shPhongLobeAt(k, -r, phongExponent);
  int coarsest = cascadeLevels - 1;
  float step = marchStepCells * cascadeLevel[coarsest].w;
  vec3 sum = vec3(0.0);
  int inside = 0;
  for (int j = 0; j < marchSamples; ++j) {
    vec3 x = p + r * ((float(j) + 0.5) * step);
    vec3 g = cascadeGridCoordinates(x, coarsest);
    if (j > 0 && (any(lessThan(g, vec3(0.0))) || any(greaterThan(g, vec3(resolution))))) break;
    float weight = cascadeWeight(x);
    if (weight > 0.0)
      sum += weight * sampleLobe(gridFromWorld(x, gridOrigin, cellSize), lobe, false, r).value;
    ++inside;
  }
  return inside > 0 ? max(sum / float(inside), vec3(0.0)) : vec3(0.0);
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(outIndirect)))) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) return;
  float weight = cascadeWeight(position.xyz);
  if (weight == 0.0 && !GLOSSY) return;
  vec3 n = texelFetch(gNormal, pixel, 0).xyz;
  vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
  vec3 p = position.xyz + n * (normalOffsetCells * cellSize);
  float lobe[SH_MAX_COEFFICIENTS];
  for (int k = 0; k < SH_COEFFICIENTS; ++k) lobe[k] = shCosineLobeAt(k, -n);
  LobeSample diffuse = sampleLobe(gridFromWorld(p, gridOrigin, cellSize), lobe, LEAK_DAMPING, n);
  vec3 e = diffuse.value;
  if (LEAK_DAMPING) {
    float total = e.r + e.g + e.b;
    e *= leakDampingFactor(total, diffuse.slope.r + diffuse.slope.g + diffuse.slope.b,
                           leakDampingStrength);
  }
  float cs2 = cellSize * cellSize;
  vec3 radiance = weight * albedo / PI * max(e, vec3(0.0)) / cs2;
  if (GLOSSY) {
    vec3 toCamera = cameraPosition - position.xyz;
    vec3 v = dot(toCamera, toCamera) > 0.0 ? normalize(toCamera) : n;
    radiance += specularAlbedo * glossyIntensity(p, reflect(-v, n)) / cs2;
  }
  imageStore(outIndirect, pixel, imageLoad(outIndirect, pixel) + vec4(indirectScale * radiance, weight));
}
