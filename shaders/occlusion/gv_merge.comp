#version 450
// Merging two sources' geometry volumes "by the larger coefficients" (thesis 4.3): per GV cell,
// the merged cell is the whole cell (all four coefficients) of the source whose c0, the
// blocking averaged over directions, is larger; on a tie the target's is kept. Taking one
// source's cell whole, rather than a per-coefficient maximum, keeps B a sum of real surfels'
// lobes; a sum of both would count a surface seen by both views twice.
#include "gv_merge_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(std430, binding = BUFFER_TARGET) buffer Target { float target[]; };       // source 1, and the result
layout(std430, binding = BUFFER_OTHER) readonly buffer Other { float other[]; };  // source 2
layout(location = LOCATION_CELLS) uniform int cells;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= cells) return;
  if (other[i] > target[i])
    for (int k = 0; k < 4; ++k) target[k * cells + i] = other[k * cells + i];
}
