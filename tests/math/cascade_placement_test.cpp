// Cascade placement (framework/math/cascade_placement.h): levels nest exactly, stay inside their
// parents, sit on whole cells of their parents, follow the camera, and do not move when the
// camera moves by less than a cell.
#include <gtest/gtest.h>

#include <cmath>

#include "framework/math/cascade_placement.h"

namespace lpvlab {
namespace {

GridGeometry sceneGrid() {
  GridGeometry g;
  g.origin = glm::vec3(-1.0f, 0.0f, -2.0f);
  g.cellSize = 0.25f;
  g.resolution = glm::ivec3(32, 16, 24);
  return g;
}

// How far `value` is from a whole multiple of `unit`, relative to the unit.
double offGrid(double value, double unit) {
  const double ratio = value / unit;
  return std::abs(ratio - std::round(ratio));
}

TEST(CascadePlacement, OneLevelIsTheSceneGrid) {
  const std::vector<GridGeometry> levels =
      placeCascadeLevels(sceneGrid(), 1, glm::vec3(0.0f), glm::vec3(0, 0, -1), 0.25f);
  ASSERT_EQ(levels.size(), 1u);
  EXPECT_EQ(levels[0].origin, sceneGrid().origin);
  EXPECT_EQ(levels[0].cellSize, sceneGrid().cellSize);
}

TEST(CascadePlacement, LevelsHalveTheirCellsNestInsideTheirParentsOnWholeParentCells) {
  for (const glm::vec3 eye : {glm::vec3(0.3f, 1.1f, 0.7f), glm::vec3(-50.0f, 3.0f, 9.0f),
                              glm::vec3(6.9f, 3.9f, 3.9f)}) {
    const std::vector<GridGeometry> levels =
        placeCascadeLevels(sceneGrid(), 4, eye, glm::vec3(0.6f, -0.2f, -0.7f), 0.25f);
    ASSERT_EQ(levels.size(), 4u);
    EXPECT_EQ(levels[3].origin, sceneGrid().origin);
    for (int level = 0; level < 3; ++level) {
      const GridGeometry& child = levels[std::size_t(level)];
      const GridGeometry& parent = levels[std::size_t(level) + 1];
      EXPECT_EQ(child.resolution, parent.resolution);
      EXPECT_FLOAT_EQ(child.cellSize * 2.0f, parent.cellSize);
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LT(offGrid(child.origin[axis] - parent.origin[axis], parent.cellSize), 1e-4)
            << "level " << level << " axis " << axis;
        EXPECT_GE(child.origin[axis], parent.origin[axis] - 1e-5f);
        EXPECT_LE(child.origin[axis] + child.extent()[axis],
                  parent.origin[axis] + parent.extent()[axis] + 1e-5f);
      }
      const glm::ivec3 offset = childOffsetInParentCells(child, parent);
      const glm::vec3 back = parent.origin + glm::vec3(offset) * parent.cellSize;
      EXPECT_NEAR(glm::length(back - child.origin), 0.0f, 1e-5f);
    }
  }
}

TEST(CascadePlacement, FinerLevelsFollowTheCameraAndHoldWhatItLooksAt) {
  const glm::vec3 eye(1.0f, 1.5f, 2.0f), forward(0.0f, 0.0f, -1.0f);
  const std::vector<GridGeometry> levels = placeCascadeLevels(sceneGrid(), 3, eye, forward, 0.25f);
  for (int level = 0; level < 2; ++level) {
    const GridGeometry& g = levels[std::size_t(level)];
    const glm::vec3 ahead = eye + forward * (0.25f * g.extent().x);
    const glm::vec3 local = (ahead - g.origin) / g.extent();
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_GT(local[axis], 0.0f) << "level " << level;
      EXPECT_LT(local[axis], 1.0f) << "level " << level;
    }
  }
  // Moving the camera by several parent cells moves the finest level.
  const std::vector<GridGeometry> moved =
      placeCascadeLevels(sceneGrid(), 3, eye + glm::vec3(1.0f, 0.0f, 0.0f), forward, 0.25f);
  EXPECT_GT(moved[0].origin.x, levels[0].origin.x + 0.5f);
}

TEST(CascadePlacement, ACameraMoveOfLessThanACellMovesNoLevelByAFractionOfACell) {
  const glm::vec3 forward = glm::normalize(glm::vec3(0.3f, -0.1f, -1.0f));
  const glm::vec3 eye(1.02f, 1.47f, 1.96f);
  const std::vector<GridGeometry> before = placeCascadeLevels(sceneGrid(), 3, eye, forward, 0.25f);
  int unchanged = 0;
  for (int step = 1; step <= 20; ++step) {
    // Sub-cell moves of the finest level's cell size, in a random-looking direction.
    const glm::vec3 delta = glm::vec3(0.013f, -0.007f, 0.011f) * float(step) * 0.3f;
    const std::vector<GridGeometry> after =
        placeCascadeLevels(sceneGrid(), 3, eye + delta, forward, 0.25f);
    bool same = true;
    for (int level = 0; level < 3; ++level) {
      const glm::vec3 shift = after[std::size_t(level)].origin - before[std::size_t(level)].origin;
      const float parentCell = before[std::size_t(level)].cellSize * (level < 2 ? 2.0f : 1.0f);
      for (int axis = 0; axis < 3; ++axis)
        EXPECT_LT(offGrid(shift[axis], parentCell), 1e-4) << "a level moved by part of a cell";
      same = same && glm::length(shift) == 0.0f;
    }
    unchanged += same;
  }
  // The smallest moves leave every level exactly where it was.
  EXPECT_GE(unchanged, 1);
}

TEST(CascadePlacement, DegenerateInputsGiveValidLevels) {
  GridGeometry tiny;
  tiny.origin = glm::vec3(0.0f);
  tiny.cellSize = 1e-6f;
  tiny.resolution = glm::ivec3(1);
  for (const GridGeometry& g : placeCascadeLevels(tiny, 8, glm::vec3(1e9f), glm::vec3(0.0f), 1.0f)) {
    EXPECT_TRUE(std::isfinite(g.origin.x) && std::isfinite(g.origin.y) && std::isfinite(g.origin.z));
    EXPECT_GT(g.cellSize, 0.0f);
  }
}

}  // namespace
}  // namespace lpvlab
