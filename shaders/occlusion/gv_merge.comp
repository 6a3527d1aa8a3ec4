#version 450
// Merging two geometry volumes "by the larger coefficients": gvMergeTakesOther
// (common/geometry_volume.glsl) per GV cell, all four coefficients of the chosen source. Two
// sources of one frame (the camera's and the light views' GVs) share one albedo buffer, to which
// both add; merging a frame's GV with the GV of the frames before (a GV history,
// variants/occlusion/geometry_volume.cpp), WITH_ALBEDO also takes the chosen source's albedo sums
// (rho A, A) with its cell.
#include "../common/geometry_volume.glsl"
#include "gv_merge_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const bool WITH_ALBEDO = false;
layout(std430, binding = BUFFER_TARGET) buffer Target { float target[]; };       // source 1, and the result
layout(std430, binding = BUFFER_OTHER) readonly buffer Other { float other[]; };  // source 2
layout(std430, binding = BUFFER_TARGET_ALBEDO) buffer TargetAlbedo { vec4 targetAlbedo[]; };
layout(std430, binding = BUFFER_OTHER_ALBEDO) readonly buffer OtherAlbedo { vec4 otherAlbedo[]; };
layout(location = LOCATION_CELLS) uniform int cells;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= cells) return;
  if (gvMergeTakesOther(target[i], other[i])) {
    for (int k = 0; k < 4; ++k) target[k * cells + i] = other[k * cells + i];
    if (WITH_ALBEDO) targetAlbedo[i] = otherAlbedo[i];
  }
}
