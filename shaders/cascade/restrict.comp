#version 450
// Carries a finer cascade level's injected light into its parent (restrict.glsl): one invocation
// per parent cell inside the child.
#include "../common/grid.glsl"

#include "restrict_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;

layout(std430, binding = BUFFER_CHILD) readonly buffer Child { float child[]; };
layout(std430, binding = BUFFER_PARENT) buffer Parent { float parent[]; };

layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;   // of both levels (cascades keep cell counts)
layout(location = LOCATION_CHILD_OFFSET) uniform ivec3 childOffset;  // the child's first cell, in parent cells

float childCoefficient(int index) { return child[index]; }
#include "restrict.glsl"

void main() {
  ivec3 c = ivec3(gl_GlobalInvocationID);      // parent cell, counted from childOffset
  if (any(greaterThanEqual(c, resolution / 2))) return;  // an odd last child cell covers half a parent cell
  int cells = cellCount(resolution);
  int parentIndex = cellIndex(childOffset + c, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < SH_COEFFICIENTS; ++k)
      parent[coefficientIndex(channel, k, SH_COEFFICIENTS, parentIndex, cells)] =
          restrictedCoefficient(channel, k, SH_COEFFICIENTS, c, resolution);
}
