// Grid addressing (shaders/common/grid.glsl as C++) at edges and corners, positions outside the
// grid, and fitting a grid to scene bounds.

#include <gtest/gtest.h>

#include <set>

#include "framework/core/error.h"
#include "framework/math/bounds.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"

namespace lpvlab {
namespace {

using glm::ivec3;

TEST(GridAddressing, IndicesAreABijectionOntoTheCells) {
  const ivec3 res(5, 3, 4);
  std::set<int> seen;
  for (int z = 0; z < res.z; ++z)
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) {
        const int index = shared::cellIndex(ivec3(x, y, z), res);
        EXPECT_GE(index, 0);
        EXPECT_LT(index, shared::cellCount(res));
        seen.insert(index);
      }
  EXPECT_EQ(int(seen.size()), shared::cellCount(res));
  EXPECT_EQ(shared::cellIndex(ivec3(0, 0, 0), res), 0);
  EXPECT_EQ(shared::cellIndex(ivec3(4, 2, 3), res), shared::cellCount(res) - 1);
  EXPECT_EQ(shared::cellIndex(ivec3(1, 0, 0), res), 1);  // x fastest
  EXPECT_EQ(shared::cellIndex(ivec3(0, 1, 0), res), res.x);
  EXPECT_EQ(shared::cellIndex(ivec3(0, 0, 1), res), res.x * res.y);
}

TEST(GridAddressing, InsideAtEdgesAndCornersOutsideBeyond) {
  const ivec3 res(4, 4, 4);
  for (int corner = 0; corner < 8; ++corner) {
    const ivec3 c((corner & 1) ? 3 : 0, (corner & 2) ? 3 : 0, (corner & 4) ? 3 : 0);
    EXPECT_TRUE(shared::cellInside(c, res));
  }
  for (int axis = 0; axis < 3; ++axis) {
    ivec3 below(1), above(1);
    below[axis] = -1;
    above[axis] = 4;
    EXPECT_FALSE(shared::cellInside(below, res));
    EXPECT_FALSE(shared::cellInside(above, res));
  }
}

TEST(GridAddressing, WorldPositionsMapToTheCellThatContainsThem) {
  const glm::dvec3 origin(-1.0, 2.0, 0.5);
  const double cell = 0.25;
  // The last cell's far boundary is outside: cells are half-open [c, c+1).
  const auto cellOf = [&](glm::dvec3 p) {
    return shared::cellContaining(shared::gridFromWorld(p, origin, cell));
  };
  EXPECT_EQ(cellOf(origin), ivec3(0));
  EXPECT_EQ(cellOf(origin + glm::dvec3(0.2499, 0.25, 0.9999)), ivec3(0, 1, 3));
  EXPECT_EQ(cellOf(origin + glm::dvec3(1.0, 0.0, 0.0)), ivec3(4, 0, 0));
  EXPECT_FALSE(shared::cellInside(cellOf(origin + glm::dvec3(1.0, 0.1, 0.1)), ivec3(4)));
  EXPECT_FALSE(shared::cellInside(cellOf(origin - glm::dvec3(1e-9, 0.0, 0.0)), ivec3(4)));
  const glm::dvec3 g(1.5, 2.5, 3.5);
  const glm::dvec3 back = shared::gridFromWorld(shared::worldFromGrid(g, origin, cell), origin, cell);
  EXPECT_NEAR(glm::length(back - g), 0.0, 1e-12);
}

TEST(GridAddressing, CoefficientLayoutIsStructureOfArrays) {
  const int cells = 10, coefficients = 4;
  EXPECT_EQ(shared::coefficientIndex(0, 0, coefficients, 7, cells), 7);
  EXPECT_EQ(shared::coefficientIndex(0, 1, coefficients, 0, cells), cells);
  EXPECT_EQ(shared::coefficientIndex(2, 3, coefficients, 9, cells), (2 * 4 + 3) * cells + 9);
}

TEST(GridGeometry, FittedGridCoversTheBoundsWithCubicCells) {
  Bounds b;
  b.extend({0, 0, 0});
  b.extend({2.0f, 0.5f, 1.0f});
  const GridGeometry g = GridGeometry::fitted(b, 32, 1.0f);
  EXPECT_EQ(g.resolution.x, 32);
  EXPECT_FLOAT_EQ(g.cellSize, 2.0f / 30.0f);
  EXPECT_LT(g.resolution.y, 32);  // a flat axis is not padded to a cube
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_LE(g.origin[axis], b.min[axis] + 1e-5f);
    EXPECT_GE(g.origin[axis] + g.resolution[axis] * g.cellSize, b.max[axis] - 1e-5f);
  }
}

TEST(GridGeometry, DegenerateAndExtremeFits) {
  Bounds point;
  point.extend({1, 1, 1});
  const GridGeometry g = GridGeometry::fitted(point, 8, 1.0f);
  EXPECT_GT(g.cellSize, 0.0f);
  EXPECT_TRUE(std::isfinite(g.origin.x));
  Bounds unit;
  unit.extend({0, 0, 0});
  unit.extend({1, 1, 1});
  EXPECT_EQ(GridGeometry::fitted(unit, 1, 0.0f).resolution, ivec3(1));
  EXPECT_EQ(GridGeometry::fitted(unit, 256, 0.0f).cellCount(), 256 * 256 * 256);
  EXPECT_THROW(GridGeometry::fitted(unit, 2, 1.0f), Error);  // margins leave nothing
  EXPECT_THROW(GridGeometry::fitted(Bounds{}, 8, 1.0f), Error);
}

}  // namespace
}  // namespace lpvlab
