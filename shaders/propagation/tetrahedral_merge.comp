#version 450
// Tetrahedral lattice -> cubic light grid: every cube takes half of each of its 24 cells (the 12
// for which it is the lower cube and the 12 for which it is the upper one; flux conserving).
// The lattice's last step becomes the grid's `current`, and its running sum, weighted by the
// step length (TET_STEP_LENGTH), is added to `accumulated`. Any SH order: SH_COEFFICIENTS per channel.
#include "tetrahedral_merge_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;

layout(std430, binding = BUFFER_LAST) readonly buffer Last { float last[]; };
layout(std430, binding = BUFFER_SUM) readonly buffer Sum { float sum[]; };
layout(std430, binding = BUFFER_CURRENT) writeonly buffer Current { float current[]; };
layout(std430, binding = BUFFER_ACCUMULATED) buffer Accumulated { float accumulated[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;

const int N = SH_COEFFICIENTS;
#include "tetrahedral_lattice.glsl"

void main() {
  ivec3 cube = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cube, resolution)) return;
  int slots = tetSlotCount(resolution);
  float lastSum[3 * N];
  float sumSum[3 * N];
  for (int i = 0; i < 3 * N; ++i) {
    lastSum[i] = 0.0;
    sumSum[i] = 0.0;
  }
  for (int code = 0; code < TET_PER_CUBE; ++code) {
    for (int side = 0; side < 2; ++side) {
      ivec3 lower = cube - side * tetUnitOffset(tetAxis(code));
      ivec4 tet = ivec4(lower.x, lower.y, lower.z, code);
      if (!tetInside(tet, resolution)) continue;
      int slot = tetSlot(tet, resolution);
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < N; ++k) {
          lastSum[channel * N + k] += last[coefficientIndex(channel, k, N, slot, slots)];
          sumSum[channel * N + k] += sum[coefficientIndex(channel, k, N, slot, slots)];
        }
    }
  }
  int cells = cellCount(resolution);
  int index = cellIndex(cube, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < N; ++k) {
      int i = coefficientIndex(channel, k, N, index, cells);
      current[i] = TET_MERGE_WEIGHT * lastSum[channel * N + k];
      accumulated[i] += TET_STEP_LENGTH * TET_MERGE_WEIGHT * sumSum[channel * N + k];
    }
}
