// Trilinear rendering on the CPU on dual numbers (trilinear_cpu.h): the pass of
// trilinear_cpu_body.h with the shared GLSL on Dual (framework/math/dual.h).
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/cpu_dispatch.h"
#include "framework/core/error.h"
#define LPVLAB_SHARED_DUAL 1
#include "framework/math/shared.h"
#include "variants/rendering/trilinear_cpu.h"

#include "variants/rendering/trilinear_cpu_body.h"

namespace lpvlab {

void trilinearDiffuseDual(const HostImage& position, const HostImage& normal,
                          const HostImage& albedo, std::span<const TrilinearLevelOf<Dual>> levels,
                          const TrilinearSettingsOf<Dual>& settings, DualTexelImage& indirect) {
  checkTrilinearInputs(position, normal, albedo, indirect.width, indirect.height, levels.size());
  addLevels(position, normal, albedo, levels, settings, indirect);
}

}  // namespace lpvlab
