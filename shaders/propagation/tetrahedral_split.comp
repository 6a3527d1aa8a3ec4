#version 450
// Cubic light grid -> tetrahedral lattice: every cell takes its share of each of its two cubes'
// coefficients (tetSplitWeight, flux conserving); slots of cells that do not exist get zero.
// Any SH order: SH_COEFFICIENTS per channel.
#include "tetrahedral_split_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;

layout(std430, binding = BUFFER_CUBES) readonly buffer Cubes { float cubes[]; };
layout(std430, binding = BUFFER_CELLS) writeonly buffer Cells { float cells[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;

const int N = SH_COEFFICIENTS;
#include "tetrahedral_slot.glsl"

void main() {
  ivec4 tet = tetOfInvocation(gl_GlobalInvocationID);
  ivec3 cube = ivec3(tet.x, tet.y, tet.z);
  if (!cellInside(cube, resolution)) return;
  int slot = tetSlot(tet, resolution);
  int slots = tetSlotCount(resolution);
  bool inside = tetInside(tet, resolution);
  ivec3 upper = cube + tetUnitOffset(tetAxis(tet.w));
  int cubeCells = cellCount(resolution);
  int lowerIndex = cellIndex(cube, resolution);
  int upperIndex = inside ? cellIndex(upper, resolution) : 0;
  float lowerWeight = tetSplitWeight(cube, resolution);
  float upperWeight = inside ? tetSplitWeight(upper, resolution) : 0.0;
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < N; ++k) {
      float value = 0.0;
      if (inside)
        value = lowerWeight * cubes[coefficientIndex(channel, k, N, lowerIndex, cubeCells)] +
                upperWeight * cubes[coefficientIndex(channel, k, N, upperIndex, cubeCells)];
      cells[coefficientIndex(channel, k, N, slot, slots)] = value;
    }
}
