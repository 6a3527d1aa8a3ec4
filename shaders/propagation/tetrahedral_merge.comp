#version 450
// Tetrahedral lattice -> cubic light grid: every cube takes half of each of its 24 cells (the 12
// for which it is the lower cube and the 12 for which it is the upper one; flux conserving).
// The lattice's last step becomes the grid's `current`, and its running sum is added to
// `accumulated`.
#include "tetrahedral_lattice.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = 0) readonly buffer Last { float last[]; };
layout(std430, binding = 1) readonly buffer Sum { float sum[]; };
layout(std430, binding = 2) writeonly buffer Current { float current[]; };
layout(std430, binding = 3) buffer Accumulated { float accumulated[]; };
layout(location = 0) uniform ivec3 resolution;

void main() {
  ivec3 cube = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cube, resolution)) return;
  int slots = tetSlotCount(resolution);
  vec4 lastSum[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  vec4 sumSum[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  for (int code = 0; code < TET_PER_CUBE; ++code) {
    for (int side = 0; side < 2; ++side) {
      ivec3 lower = cube - side * tetUnitOffset(tetAxis(code));
      ivec4 tet = ivec4(lower.x, lower.y, lower.z, code);
      if (!tetInside(tet, resolution)) continue;
      int slot = tetSlot(tet, resolution);
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < 4; ++k) {
          lastSum[channel][k] += last[coefficientIndex(channel, k, 4, slot, slots)];
          sumSum[channel][k] += sum[coefficientIndex(channel, k, 4, slot, slots)];
        }
    }
  }
  int cells = cellCount(resolution);
  int index = cellIndex(cube, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < 4; ++k) {
      int i = coefficientIndex(channel, k, 4, index, cells);
      current[i] = TET_MERGE_WEIGHT * lastSum[channel][k];
      accumulated[i] += TET_MERGE_WEIGHT * sumSum[channel][k];
    }
}
