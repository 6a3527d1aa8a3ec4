#include "variants/rendering/subsurface_cpu.h"

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#define LPVLAB_SHARED_SINGLE_PRECISION 1
#include "framework/math/shared.h"

// subsurface_exit.glsl over one SSLPV on the host: it reads the grid through
// subsurfaceGridValue; its own includes come first, at namespace scope.
LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/rendering/trilinear_weights.glsl"
#include "shaders/subsurface/subsurface.glsl"
struct SubsurfaceExitKernel {
  const float* grid;
  int SH_COEFFICIENTS;
  real subsurfaceGridValue(int channel, int k, int cell, int cells) const {
    return real(grid[coefficientIndex(channel, k, SH_COEFFICIENTS, cell, cells)]);
  }
#include "shaders/subsurface/subsurface_exit.glsl"
};
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

void addSubsurfaceLightCpu(const SubsurfaceShadingInputs& in, HostImage& indirect) {
  const int w = indirect.width, h = indirect.height;
  for (const HostImage* image : {in.position, in.normal, in.mask})
    if (!image || image->width != w || image->height != h)
      throw Error("rendering \"subsurface\" (CPU): an input image is missing or not the indirect "
                  "image's size");
  const GridGeometry& g = in.geometry;
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      runAtLevel(in.instructions, [&] {
        shared::SubsurfaceExitKernel kernel{in.accumulated, in.coefficients};
        for (int x = 0; x < w; ++x) {
          const std::size_t p = std::size_t(y) * w + x;
          if (in.mask->texels[p].r < 0.5f) continue;
          const glm::vec4 position = in.position->texels[p];
          if (position.w == 0.0f) continue;
          const glm::vec3 n(in.normal->texels[p]);  // faces the camera: outward on a closed object
          const glm::vec3 radiance = kernel.subsurfaceExitingRadiance(
              glm::vec3(position), n, g.origin, g.cellSize, g.resolution);
          indirect.texels[p] += glm::vec4(radiance, 0.0f);
        }
      });
  });
}

}  // namespace lpvlab
