#pragma once
// For the CPU propagation kernels (standard_cpu_kernels.h, tetrahedral_cpu.cpp): the GV lookup of
// geometry_volume_lookup.glsl over one GV buffer of floats (coefficient-major, 4 values per GV
// cell), as `shared::GvLookup`, which their occlusion bodies call. dual_gv_lookup.h is its twin
// over Duals. Include it after the kernel's own shared GLSL, whose functions it may call.

#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
using glm::mix;
struct GvLookup {
  const float* gvBlocking;
#include "shaders/common/geometry_volume_lookup.glsl"
};
LPVLAB_SHARED_GLSL_END
