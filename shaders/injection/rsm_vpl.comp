#version 450
// Injection of every RSM texel as a virtual point light (thesis eq. 4.1-4.3): a Lambertian VPL of
// flux Phi and normal n has intensity I(w) = Phi / pi * max(0, n . w), whose coefficients
// Phi / pi * shCosineLobe(n) are added (atomically) to the cell containing the texel's position
// moved `shiftCells` cells along n (against self-illumination). Each texel's flux lands whole in
// the grid: the sum over cells of shIntegral equals the RSM's total flux, less what falls outside.
#extension GL_EXT_shader_atomic_float : require
#include "../common/sh.glsl"
#include "../common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray rsmPosition;
layout(binding = 1) uniform sampler2DArray rsmNormal;
layout(binding = 2) uniform sampler2DArray rsmFlux;
layout(std430, binding = 0) buffer Grid { float grid[]; };

layout(location = 0) uniform vec3 gridOrigin;
layout(location = 1) uniform float cellSize;
layout(location = 2) uniform ivec3 resolution;
layout(location = 3) uniform float shiftCells;
layout(location = 4) uniform int rsmResolution;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (texel.x >= rsmResolution || texel.y >= rsmResolution) return;
  vec4 flux = texelFetch(rsmFlux, texel, 0);
  if (flux.w == 0.0) return;
  vec3 n = texelFetch(rsmNormal, texel, 0).xyz;
  vec3 p = texelFetch(rsmPosition, texel, 0).xyz + n * (shiftCells * cellSize);
  ivec3 cell = cellContaining(gridFromWorld(p, gridOrigin, cellSize));
  if (!cellInside(cell, resolution)) return;
  int cells = cellCount(resolution);
  int index = cellIndex(cell, resolution);
  vec4 lobe = shCosineLobe(n) / PI;
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < 4; ++k)
      atomicAdd(grid[coefficientIndex(channel, k, 4, index, cells)], flux[channel] * lobe[k]);
}
