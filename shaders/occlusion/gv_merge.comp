#version 450
// Merging two sources' geometry volumes "by the larger coefficients" (thesis 4.3): per GV cell,
// the merged cell is the whole cell (all four coefficients) of the source whose c0, the
// blocking averaged over directions, is larger; on a tie the target's is kept. Taking one
// source's cell whole, rather than a per-coefficient maximum, keeps B a sum of real surfels'
// lobes; a sum of both would count a surface seen by both views twice.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Target { float target[]; };       // source 1, and the result
layout(std430, binding = 1) readonly buffer Other { float other[]; };  // source 2
layout(location = 0) uniform int cells;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= cells) return;
  if (other[i] > target[i])
    for (int k = 0; k < 4; ++k) target[k * cells + i] = other[k * cells + i];
}
