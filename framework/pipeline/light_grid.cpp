#include "framework/pipeline/light_grid.h"

#include "framework/core/error.h"

namespace lpvlab {

LightGrid::LightGrid(const GridGeometry& geometry_, int shOrder)
    : geometry(geometry_), coefficients((shOrder + 1) * (shOrder + 1)) {
  // Buffers are indexed with 32-bit ints in the kernels.
  const double floats = double(kChannels) * coefficients * geometry.cellCount();
  if (floats >= 2147483647.0)
    throw Error("grid: " + std::to_string(geometry.cellCount()) + " cells with " +
                std::to_string(coefficients) + " coefficients exceed 2^31 floats per buffer");
  current = DualBuffer(bytesPerGrid(), "light grid (current)");
  accumulated = DualBuffer(bytesPerGrid(), "light grid (accumulated)");
}

}  // namespace lpvlab
