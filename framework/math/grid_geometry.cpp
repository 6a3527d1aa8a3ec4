#include "framework/math/grid_geometry.h"

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "framework/math/bounds.h"

namespace lpvlab {

GridGeometry GridGeometry::fitted(const Bounds& bounds, int cellsAlongLongestAxis,
                                  float marginCells) {
  if (bounds.empty()) throw Error("grid: cannot fit a grid to empty scene bounds");
  if (cellsAlongLongestAxis < 1) throw Error("grid: resolution must be at least 1");
  if (!(marginCells >= 0.0f)) throw Error("grid: margin must be non-negative");
  const glm::vec3 extent = bounds.extent();
  float longest = std::max({extent.x, extent.y, extent.z});
  // A point-like scene still needs a grid of finite cells: give it a millimetre.
  longest = std::max(longest, 1e-3f);
  // longest + 2 * margin * cellSize = cells * cellSize.
  const float usable = static_cast<float>(cellsAlongLongestAxis) - 2.0f * marginCells;
  if (usable <= 0.0f)
    throw Error("grid: a margin of " + std::to_string(marginCells) + " cells on each side leaves no "
                "cells for the scene at resolution " + std::to_string(cellsAlongLongestAxis));
  GridGeometry grid;
  grid.cellSize = longest / usable;
  for (int axis = 0; axis < 3; ++axis) {
    const float needed = extent[axis] / grid.cellSize + 2.0f * marginCells;
    grid.resolution[axis] =
        std::clamp(static_cast<int>(std::ceil(needed - 1e-4f)), 1, cellsAlongLongestAxis);
  }
  grid.origin = bounds.center() - 0.5f * glm::vec3(grid.resolution) * grid.cellSize;
  return grid;
}

}  // namespace lpvlab
