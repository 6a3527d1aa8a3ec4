// The weight of one cascade level at a world position, in the shared GLSL/C++ subset
// (prelude.glsl): GL's rendering kernels (through cascade_blend.glsl's uniforms) and the CPU
// kernel (variants/rendering/trilinear_cpu.cpp) call these same functions. With fades a_j
// (cascade_fade.glsl) and the coarsest level's a = 1, level i's weight is
//   w_i = a_i * prod_{j < i} (1 - a_j),
// so the weights sum to 1 everywhere, only the two nearest levels overlap in a blend band, and
// each weight is continuous across level boundaries (a_j reaches 0 before the level's edge).
// The includer defines where each level lies:
//   vec3 cascadeLevelOrigin(int level)     world position of the corner of its cell (0,0,0)
//   real cascadeLevelCellSize(int level)   its cell's edge, m
#ifndef LPVLAB_CASCADE_WEIGHT_GLSL
#define LPVLAB_CASCADE_WEIGHT_GLSL
#include "cascade_fade.glsl"
#include "grid.glsl"

vec3 cascadeGridCoordinates(vec3 p, int level) {
  return gridFromWorld(p, cascadeLevelOrigin(level), cascadeLevelCellSize(level));
}

// Level `current`'s weight of `levels` (finest first), all of resolution `res`.
real cascadeLevelWeight(vec3 p, int current, int levels, ivec3 res, real blendCells) {
  real weight = current == levels - 1
      ? real(1.0)
      : cascadeFade(cascadeGridCoordinates(p, current), res, blendCells);
  for (int j = 0; j < current; ++j)
    weight *= real(1.0) - cascadeFade(cascadeGridCoordinates(p, j), res, blendCells);
  return weight;
}

#endif
