#version 450
// Carries a finer cascade level's injected light into its parent (thesis 5.1: light of levels
// with smaller cells is put into levels with larger ones): every parent cell that lies wholly
// inside the child becomes the sum of its 2x2x2 child cells. The intensities (W/sr) of emitters
// in one cell add, so flux is conserved exactly, and the parent propagates the child's sources,
// placed to the child's precision (VPLs shifted by a child cell, not a parent cell), instead of
// its own coarser injection of the same surfaces. Parent cells outside the child keep their own.
#include "../common/grid.glsl"

#include "restrict_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;

layout(std430, binding = BUFFER_CHILD) readonly buffer Child { float child[]; };
layout(std430, binding = BUFFER_PARENT) buffer Parent { float parent[]; };

layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;   // of both levels (cascades keep cell counts)
layout(location = LOCATION_CHILD_OFFSET) uniform ivec3 childOffset;  // the child's first cell, in parent cells

void main() {
  ivec3 c = ivec3(gl_GlobalInvocationID);      // parent cell, counted from childOffset
  if (any(greaterThanEqual(c, resolution / 2))) return;  // an odd last child cell covers half a parent cell
  int cells = cellCount(resolution);
  int parentIndex = cellIndex(childOffset + c, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < SH_COEFFICIENTS; ++k) {
      float sum = 0.0;
      for (int corner = 0; corner < 8; ++corner) {
        ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        sum += child[coefficientIndex(channel, k, SH_COEFFICIENTS, cellIndex(2 * c + o, resolution), cells)];
      }
      parent[coefficientIndex(channel, k, SH_COEFFICIENTS, parentIndex, cells)] = sum;
    }
}
