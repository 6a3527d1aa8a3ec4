#pragma once
// For the translation units that build a propagation's GV faces on dual numbers
// (standard_cpu_dual.cpp, tetrahedral_cpu_dual.cpp): the shared GLSL on Dual
// (framework/math/shared.h) and its GV lookup (geometry_volume_lookup.glsl) over a GV of Duals,
// as `shared::GvLookup`, which their occlusion bodies call. Include it first: it fixes the
// translation unit's shared precision.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#define LPVLAB_SHARED_DUAL 1
#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
using glm::mix;
struct GvLookup {
  const Dual* gvBlocking;
#include "shaders/common/geometry_volume_lookup.glsl"
};
LPVLAB_SHARED_GLSL_END
