// The weight of one cascade level in a rendering kernel that runs once per level and adds its
// share (framework/pipeline/cascade.h binds these uniforms): cascade_weight.glsl's, with the
// levels' placement from the uniforms below.
#ifndef LPVLAB_CASCADE_BLEND_GLSL
#define LPVLAB_CASCADE_BLEND_GLSL
#include "cascade_blend_interface.glsl"
layout(location = LOCATION_CASCADE_LEVEL) uniform vec4 cascadeLevel[CASCADE_MAX_LEVELS];  // origin xyz, cell size w
layout(location = LOCATION_CASCADE_LEVELS) uniform int cascadeLevels;
layout(location = LOCATION_CASCADE_CURRENT) uniform int cascadeCurrent;    // the level this dispatch renders
layout(location = LOCATION_CASCADE_BLEND_CELLS) uniform float cascadeBlendCells;
layout(location = LOCATION_CASCADE_RESOLUTION) uniform ivec3 cascadeResolution;  // the same for every level

vec3 cascadeLevelOrigin(int level) { return cascadeLevel[level].xyz; }
float cascadeLevelCellSize(int level) { return cascadeLevel[level].w; }
#include "cascade_weight.glsl"

float cascadeWeight(vec3 p) {
  return cascadeLevelWeight(p, cascadeCurrent, cascadeLevels, cascadeResolution, cascadeBlendCells);
}

#endif
