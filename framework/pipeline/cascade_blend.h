#pragma once
// The uniforms of shaders/common/cascade_blend.glsl, which weights each cascade level where a
// rendering kernel reads it, for a kernel (in use) that renders `level` of `levels` (finest first)
// blended over `blendCells` cells. Needs only GL: the rendering kernels' launchers call it, in
// lpvlab and in lpvlab-gpubench (setCascadeBlendUniforms of cascade.h gives it a frame's levels).

#include <span>

#include "framework/math/grid_geometry.h"

namespace lpvlab {

void setCascadeBlendUniforms(std::span<const GridGeometry> levels, int level, float blendCells);

}  // namespace lpvlab
