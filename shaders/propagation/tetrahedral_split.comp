#version 450
// Cubic light grid -> tetrahedral lattice: every cell takes its share of each of its two cubes'
// coefficients (tetSplitWeight, flux conserving); slots of cells that do not exist get zero.
#include "tetrahedral_slot.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = 0) readonly buffer Cubes { float cubes[]; };
layout(std430, binding = 1) writeonly buffer Cells { float cells[]; };
layout(location = 0) uniform ivec3 resolution;

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
    for (int k = 0; k < 4; ++k) {
      float value = 0.0;
      if (inside)
        value = lowerWeight * cubes[coefficientIndex(channel, k, 4, lowerIndex, cubeCells)] +
                upperWeight * cubes[coefficientIndex(channel, k, 4, upperIndex, cubeCells)];
      cells[coefficientIndex(channel, k, 4, slot, slots)] = value;
    }
}
