#version 450
// Indirect light at every G-buffer pixel from the accumulated light grid, trilinearly
// interpolated between the 8 nearest cell centres (clamped at the grid's edge), at any SH order.
// One dispatch per cascade level: each adds its light times the level's weight
// (cascade_blend.glsl) to the output, which the pipeline zeroed. The diffuse light, and its
// units, are trilinear_diffuse.glsl's, which the CPU kernel calls too.
// Options (specialisation constants, so "trilinear" alone pays for neither):
//   LEAK_DAMPING: the diffuse read is damped (leak_damping.glsl).
//   GLOSSY:       adds specularAlbedo * the grid's radiance arriving from the reflected view
//                 direction r, weighted by a normalised Phong lobe (phong_lobe.glsl) and averaged
//                 over samples marched along r (docs/variants/glossy.md#glossy).
#include "../common/cascade_blend.glsl"

#include "trilinear_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;
layout(constant_id = 1) const bool LEAK_DAMPING = false;
layout(constant_id = 2) const bool GLOSSY = false;

layout(binding = UNIT_G_POSITION) uniform sampler2D gPosition;
layout(binding = UNIT_G_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_G_ALBEDO) uniform sampler2D gAlbedo;
layout(std430, binding = BUFFER_ACCUMULATED) readonly buffer Accumulated { float grid[]; };
float gridCoefficient(int channel, int k, int coefficients, int cell, int cells) {
  return grid[coefficientIndex(channel, k, coefficients, cell, cells)];
}
#include "glossy_march.glsl"
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

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(outIndirect)))) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) return;
  float weight = cascadeWeight(position.xyz);
  if (weight == 0.0 && !GLOSSY) return;
  vec3 n = texelFetch(gNormal, pixel, 0).xyz;
  vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
  vec3 radiance = weight * trilinearDiffuse(position.xyz, n, albedo, gridOrigin, cellSize, resolution,
                                            SH_COEFFICIENTS, normalOffsetCells,
                                            LEAK_DAMPING ? leakDampingStrength : 0.0);
  if (GLOSSY)
    radiance += glossyRadiance(position.xyz, n, cameraPosition, specularAlbedo, normalOffsetCells,
                               GlossyMarch(phongExponent, marchStepCells, marchSamples,
                                           cascadeCurrent, cascadeLevels, resolution,
                                           cascadeBlendCells),
                               gridOrigin, cellSize, SH_COEFFICIENTS);
  imageStore(outIndirect, pixel, imageLoad(outIndirect, pixel) + vec4(indirectScale * radiance, weight));
}
