#pragma once
// The light grid: RGB SH coefficients of radiant intensity (W/sr) per cell, in buffers laid out as
// shaders/common/grid.glsl describes (structure of arrays, coefficient-major), on GL and, when a
// CPU kernel uses them, on the host (dual_buffer.h: each side brought up to date on demand).
//   current:     the light of the latest propagation step (after injection: the injected VPLs)
//   accumulated: the sum over injection and every propagation step, which rendering reads
// Propagation strategies allocate their own scratch (e.g. a ping-pong partner for `current`).

#include <cstddef>

#include "framework/math/grid_geometry.h"
#include "framework/gl/dual_buffer.h"

namespace lpvlab {

struct LightGrid {
  static constexpr int kChannels = 3;

  GridGeometry geometry;
  int coefficients = 4;  // per channel: (order + 1)^2
  DualBuffer current;
  DualBuffer accumulated;

  LightGrid() = default;
  LightGrid(const GridGeometry& geometry, int shOrder);

  // Bytes of one grid of this layout (current, accumulated, or a strategy's scratch copy).
  static std::size_t bytesPerGrid(const GridGeometry& geometry, int shOrder) {
    return std::size_t(kChannels) * (shOrder + 1) * (shOrder + 1) * geometry.cellCount() * sizeof(float);
  }
  std::size_t floatsPerGrid() const {
    return std::size_t(kChannels) * coefficients * geometry.cellCount();
  }
  std::size_t bytesPerGrid() const { return floatsPerGrid() * sizeof(float); }
  std::size_t memoryBytes() const { return current.memoryBytes() + accumulated.memoryBytes(); }
};

}  // namespace lpvlab
