#include "variants/injection/sky_columns_cpu.h"

#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/injection/sky_columns.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

void injectSkyColumnsCpu(const std::vector<float>& depth, int width, int height,
                         const GridGeometry& grid, int coefficients, float shiftCells,
                         const glm::vec3& perTexel, bool everyFreeCell, float* gridOut) {
  const glm::ivec3 res = grid.resolution;
  if (width % res.x != 0 || height % res.z != 0 || depth.size() != std::size_t(width) * height)
    throw Error("sky injection (CPU): a " + std::to_string(width) + "x" + std::to_string(height) +
                " depth map does not tile the grid's " + std::to_string(res.x) + "x" +
                std::to_string(res.z) + " columns evenly");
  const int texelsX = width / res.x, texelsZ = height / res.z;  // per column
  const int cells = grid.cellCount();
  std::vector<double> lobe(static_cast<std::size_t>(coefficients));
  for (int k = 0; k < coefficients; ++k) lobe[std::size_t(k)] = shared::skyDownwardLobeAt(k);
  const glm::dvec3 origin(grid.origin);
  tbb::parallel_for(tbb::blocked_range<int>(0, res.x * res.z), [&](const tbb::blocked_range<int>& r) {
    std::vector<double> layerWeight(std::size_t(res.y));  // texels lighting each layer
    for (int column = r.begin(); column < r.end(); ++column) {
      const int cx = column % res.x, cz = column / res.x;
      // How many texels of this column light each layer: every texel brings the same L a, so
      // the layer's light is that count times it.
      std::fill(layerWeight.begin(), layerWeight.end(), 0.0);
      for (int tz = cz * texelsZ; tz < (cz + 1) * texelsZ; ++tz)
        for (int tx = cx * texelsX; tx < (cx + 1) * texelsX; ++tx) {
          const double d = depth[std::size_t(tz) * width + tx];
          if (d >= 1.0) continue;
          const glm::ivec3 cell = shared::skyColumnCell(glm::ivec2(tx, tz), glm::ivec2(width, height),
                                                        d, origin, double(grid.cellSize), res,
                                                        double(shiftCells));
          const int top = shared::skyTopLayer(cell.y, res.y, everyFreeCell ? 1 : 0);
          for (int layer = cell.y; layer <= top; ++layer) layerWeight[std::size_t(layer)] += 1.0;
        }
      for (int y = 0; y < res.y; ++y) {
        const double count = layerWeight[std::size_t(y)];
        if (count == 0.0) continue;
        const int index = shared::cellIndex(glm::ivec3(cx, y, cz), res);
        for (int channel = 0; channel < 3; ++channel)
          for (int k = 0; k < coefficients; ++k)
            gridOut[shared::coefficientIndex(channel, k, coefficients, index, cells)] +=
                float(count * double(perTexel[channel]) * lobe[std::size_t(k)]);
      }
    }
  });
}

}  // namespace lpvlab
