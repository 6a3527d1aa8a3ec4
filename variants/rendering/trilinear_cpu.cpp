#include "variants/rendering/trilinear_cpu.h"

#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/cpu_dispatch.h"
#include "framework/core/error.h"
#define LPVLAB_SHARED_SINGLE_PRECISION 1
#include "framework/math/shared.h"

namespace lpvlab {

namespace blend_kernel {
#include "shaders/common/cascade_blend_interface.glsl"
}

}  // namespace lpvlab

#include "variants/rendering/trilinear_cpu_body.h"

namespace lpvlab {

void checkTrilinearInputs(const HostImage& position, const HostImage& normal,
                          const HostImage& albedo, int indirectWidth, int indirectHeight,
                          std::size_t levels) {
  for (const HostImage* image : {&normal, &albedo})
    if (image->width != position.width || image->height != position.height)
      throw Error("trilinear rendering (CPU): the G-buffer and the output differ in size");
  if (indirectWidth != position.width || indirectHeight != position.height)
    throw Error("trilinear rendering (CPU): the G-buffer and the output differ in size");
  if (levels > std::size_t(blend_kernel::CASCADE_MAX_LEVELS))
    throw Error("trilinear rendering (CPU): at most " +
                std::to_string(blend_kernel::CASCADE_MAX_LEVELS) + " levels can be rendered");
}

void trilinearDiffuseCpu(const HostImage& position, const HostImage& normal,
                         const HostImage& albedo, std::span<const TrilinearCpuLevel> levels,
                         const TrilinearCpuSettings& settings, HostImage& indirect) {
  checkTrilinearInputs(position, normal, albedo, indirect.width, indirect.height, levels.size());
  addLevels(position, normal, albedo, levels, settings, indirect);
}

}  // namespace lpvlab
