#version 450
// Merging two sources' geometry volumes "by the larger coefficients": gvMergeTakesOther
// (common/geometry_volume.glsl) per GV cell, all four coefficients of the chosen source.
#include "../common/geometry_volume.glsl"
#include "gv_merge_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(std430, binding = BUFFER_TARGET) buffer Target { float target[]; };       // source 1, and the result
layout(std430, binding = BUFFER_OTHER) readonly buffer Other { float other[]; };  // source 2
layout(location = LOCATION_CELLS) uniform int cells;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= cells) return;
  if (gvMergeTakesOther(target[i], other[i]))
    for (int k = 0; k < 4; ++k) target[k * cells + i] = other[k * cells + i];
}
