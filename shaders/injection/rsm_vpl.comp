#version 450
// Injection of every RSM texel as a virtual point light (vpl.glsl: its cell and its coefficients,
// any SH order), added atomically. Each texel's flux lands whole in the grid: the sum over cells
// of the SH integral equals the RSM's total flux, less what falls outside.
// With a normal grid (directed propagation), the flux-weighted normal, and the weight, are added
// to the same cell: xyz = sum Phi n, w = sum Phi (Phi summed over RGB).
#extension GL_EXT_shader_atomic_float : require
#include "vpl.glsl"

#include "rsm_vpl_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;
layout(constant_id = 1) const bool WRITE_NORMALS = false;

layout(binding = UNIT_RSM_POSITION) uniform sampler2DArray rsmPosition;
layout(binding = UNIT_RSM_NORMAL) uniform sampler2DArray rsmNormal;
layout(binding = UNIT_RSM_FLUX) uniform sampler2DArray rsmFlux;
layout(std430, binding = BUFFER_GRID) buffer Grid { float grid[]; };
layout(std430, binding = BUFFER_NORMALS) buffer Normals { vec4 normals[]; };

layout(location = LOCATION_GRID_ORIGIN) uniform vec3 gridOrigin;
layout(location = LOCATION_CELL_SIZE) uniform float cellSize;
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_SHIFT_CELLS) uniform float shiftCells;
layout(location = LOCATION_RSM_RESOLUTION) uniform int rsmResolution;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (texel.x >= rsmResolution || texel.y >= rsmResolution) return;
  vec4 flux = texelFetch(rsmFlux, texel, 0);
  if (flux.w == 0.0) return;
  vec3 n = texelFetch(rsmNormal, texel, 0).xyz;
  ivec3 cell = vplCell(texelFetch(rsmPosition, texel, 0).xyz, n, gridOrigin, cellSize, shiftCells);
  if (!cellInside(cell, resolution)) return;
  int cells = cellCount(resolution);
  int index = cellIndex(cell, resolution);
  for (int k = 0; k < SH_COEFFICIENTS; ++k) {
    float lobe = vplLobeAt(k, n);
    for (int channel = 0; channel < 3; ++channel)
      atomicAdd(grid[coefficientIndex(channel, k, SH_COEFFICIENTS, index, cells)], flux[channel] * lobe);
  }
  if (WRITE_NORMALS) {
    float weight = flux.r + flux.g + flux.b;
    atomicAdd(normals[index].x, weight * n.x);
    atomicAdd(normals[index].y, weight * n.y);
    atomicAdd(normals[index].z, weight * n.z);
    atomicAdd(normals[index].w, weight);
  }
}
