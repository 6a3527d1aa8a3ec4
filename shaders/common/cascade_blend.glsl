// The weight of one cascade level in a rendering kernel that runs once per level and adds its
// share (framework/pipeline/cascade.h binds these uniforms). With fades a_j (cascade_fade.glsl)
// and the coarsest level's a = 1, level i's weight is
//   w_i = a_i * prod_{j < i} (1 - a_j),
// so the weights sum to 1 everywhere, only the two nearest levels overlap in a blend band, and
// each weight is continuous across level boundaries (a_j reaches 0 before the level's edge).
#ifndef LPVLAB_CASCADE_BLEND_GLSL
#define LPVLAB_CASCADE_BLEND_GLSL
#include "cascade_fade.glsl"
#include "grid.glsl"

#include "cascade_blend_interface.glsl"
layout(location = LOCATION_CASCADE_LEVEL) uniform vec4 cascadeLevel[CASCADE_MAX_LEVELS];  // origin xyz, cell size w
layout(location = LOCATION_CASCADE_LEVELS) uniform int cascadeLevels;
layout(location = LOCATION_CASCADE_CURRENT) uniform int cascadeCurrent;    // the level this dispatch renders
layout(location = LOCATION_CASCADE_BLEND_CELLS) uniform float cascadeBlendCells;
layout(location = LOCATION_CASCADE_RESOLUTION) uniform ivec3 cascadeResolution;  // the same for every level

vec3 cascadeGridCoordinates(vec3 p, int level) {
  return gridFromWorld(p, cascadeLevel[level].xyz, cascadeLevel[level].w);
}

float cascadeWeight(vec3 p) {
  float weight = cascadeCurrent == cascadeLevels - 1
      ? 1.0
      : cascadeFade(cascadeGridCoordinates(p, cascadeCurrent), cascadeResolution, cascadeBlendCells);
  for (int j = 0; j < cascadeCurrent; ++j)
    weight *= 1.0 - cascadeFade(cascadeGridCoordinates(p, j), cascadeResolution, cascadeBlendCells);
  return weight;
}

#endif
