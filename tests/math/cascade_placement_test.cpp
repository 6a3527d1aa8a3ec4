// Cascade placement (framework/math/cascade_placement.h): levels nest exactly, stay inside their
// parents, sit on whole cells of their parents, follow the camera, and do not move when the
// camera moves by less than a cell. "Depth" placement: every level contains the focus (even cell
// counts), the placement is piecewise constant in the focus (moves only by whole parent cells, at
// most once per parent cell the focus travels), and the focus is the per-axis median of what the
// camera sees, which outliers do not move.
#include "framework/math/cascade_placement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

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
  for (const glm::vec3 eye :
       {glm::vec3(0.3f, 1.1f, 0.7f), glm::vec3(-50.0f, 3.0f, 9.0f), glm::vec3(6.9f, 3.9f, 3.9f)}) {
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

// [cascades] snap = false: the finer levels follow the eye continuously, so every sub-cell move
// moves them by the same amount (until a level meets its parent's side) and they leave the
// parents' cells.
TEST(CascadePlacement, UnsnappedLevelsFollowEverySubCellMove) {
  const glm::vec3 forward = glm::normalize(glm::vec3(0.3f, -0.1f, -1.0f));
  const glm::vec3 eye(1.02f, 1.47f, 1.96f), delta(0.013f, -0.007f, 0.011f);
  const std::vector<GridGeometry> before =
      placeCascadeLevels(sceneGrid(), 3, eye, forward, 0.25f, false);
  const std::vector<GridGeometry> after =
      placeCascadeLevels(sceneGrid(), 3, eye + delta, forward, 0.25f, false);
  for (int level = 0; level < 2; ++level) {
    const glm::vec3 shift = after[std::size_t(level)].origin - before[std::size_t(level)].origin;
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(shift[axis], delta[axis], 1e-5f) << level;
    // Centred on the wanted point, not on a parent cell.
    const glm::vec3 centre =
        before[std::size_t(level)].origin + 0.5f * before[std::size_t(level)].extent();
    const GridGeometry& parent = before[std::size_t(level) + 1];
    const float longest = 0.5f * parent.cellSize * 32.0f;
    EXPECT_LT(glm::length(centre - (eye + forward * (0.25f * longest))), 1e-4f) << level;
  }
  EXPECT_EQ(after.back().origin, sceneGrid().origin);  // the coarsest never moves
  // The snapped levels of the same move: on whole parent cells (the test above).
  const std::vector<GridGeometry> snapped = placeCascadeLevels(sceneGrid(), 3, eye, forward, 0.25f);
  EXPECT_GT(offGrid(before[0].origin.x - before[1].origin.x, before[1].cellSize), 1e-3);
  EXPECT_LT(offGrid(snapped[0].origin.x - snapped[1].origin.x, snapped[1].cellSize), 1e-4);
}

// Levels nest in their parents on whole parent cells (what carrying and no-flicker rely on).
void expectNested(const std::vector<GridGeometry>& levels) {
  for (std::size_t level = 0; level + 1 < levels.size(); ++level) {
    const GridGeometry& child = levels[level];
    const GridGeometry& parent = levels[level + 1];
    EXPECT_FLOAT_EQ(child.cellSize * 2.0f, parent.cellSize);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_LT(offGrid(child.origin[axis] - parent.origin[axis], parent.cellSize), 1e-4);
      EXPECT_GE(child.origin[axis], parent.origin[axis] - 1e-5f);
      EXPECT_LE(child.origin[axis] + child.extent()[axis],
                parent.origin[axis] + parent.extent()[axis] + 1e-5f);
    }
  }
}

TEST(CascadePlacement, DepthPlacementNestsAndEveryLevelContainsTheFocus) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (const glm::ivec3 resolution :
       {glm::ivec3(32, 16, 24), glm::ivec3(2, 4, 6), glm::ivec3(12)}) {
    GridGeometry grid = sceneGrid();
    grid.resolution = resolution;
    for (int trial = 0; trial < 200; ++trial) {
      // Anywhere in the scene grid, its corners and faces included.
      glm::vec3 focus =
          grid.origin + grid.extent() * glm::vec3(unit(random), unit(random), unit(random));
      if (trial % 4 == 0) focus.x = grid.origin.x;
      if (trial % 4 == 1) focus.y = grid.origin.y + grid.extent().y;
      const std::vector<GridGeometry> levels = placeCascadeLevels(grid, 5, focus);
      ASSERT_EQ(levels.size(), 5u);
      EXPECT_EQ(levels[4].origin, grid.origin);
      expectNested(levels);
      for (std::size_t level = 0; level < 4; ++level) {
        const glm::vec3 local = (focus - levels[level].origin) / levels[level].extent();
        for (int axis = 0; axis < 3; ++axis) {
          EXPECT_GE(local[axis], -1e-5f) << "level " << level << " axis " << axis;
          EXPECT_LE(local[axis], 1.0f + 1e-5f) << "level " << level << " axis " << axis;
        }
      }
    }
  }
  // The finest level is centred on the focus to within one of its cells, away from the sides.
  const glm::vec3 focus = sceneGrid().origin + sceneGrid().extent() * glm::vec3(0.45f, 0.55f, 0.5f);
  const GridGeometry finest = placeCascadeLevels(sceneGrid(), 3, focus)[0];
  const glm::vec3 off = glm::abs(finest.origin + 0.5f * finest.extent() - focus);
  for (int axis = 0; axis < 3; ++axis) EXPECT_LE(off[axis], finest.cellSize * (1.0f + 1e-4f));
}

TEST(CascadePlacement, DepthPlacementMovesOnlyByWholeParentCellsAndOncePerParentCellTravelled) {
  const glm::vec3 start = sceneGrid().origin + sceneGrid().extent() * glm::vec3(0.4f, 0.5f, 0.45f);
  const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, 0.3f, -0.2f));
  const float finestParentCell = sceneGrid().cellSize / 2.0f;  // level 1's cells, of 3 levels
  const int steps = 400;
  const float step = finestParentCell / 50.0f;  // 8 of the finest level's parent cells in all
  std::vector<GridGeometry> previous = placeCascadeLevels(sceneGrid(), 3, start);
  int moves = 0, unchanged = 0;
  for (int i = 1; i <= steps; ++i) {
    const std::vector<GridGeometry> placed =
        placeCascadeLevels(sceneGrid(), 3, start + direction * (step * float(i)));
    const glm::vec3 shift = placed[0].origin - previous[0].origin;
    if (shift == glm::vec3(0.0f)) {
      ++unchanged;
    } else {
      ++moves;
      // One plane crossed at a time: a single whole parent cell along one axis.
      float moved = 0.0f;
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LT(offGrid(shift[axis], finestParentCell), 1e-4);
        moved += std::abs(shift[axis]) / finestParentCell;
      }
      EXPECT_NEAR(moved, 1.0f, 1e-3f) << "step " << i;
    }
    previous = placed;
  }
  // Along the walk the focus crosses at most 8 + 1 planes per axis (it moves 8 cells in all).
  const glm::vec3 travelled = glm::abs(direction) * (step * float(steps)) / finestParentCell;
  EXPECT_LE(moves, int(std::ceil(travelled.x)) + int(std::ceil(travelled.y)) +
                       int(std::ceil(travelled.z)));
  EXPECT_GE(moves, int(std::floor(travelled.x)));  // it does follow the focus
  EXPECT_GT(unchanged, steps * 9 / 10);            // sub-cell moves change nothing
}

TEST(CascadePlacement, TheFocusIsThePerAxisMedianOfTheVisiblePositionsAndIgnoresOutliers) {
  EXPECT_FALSE(visibleFocus({}).has_value());
  std::mt19937 random(3);
  std::normal_distribution<float> spread(0.0f, 0.05f);
  const glm::vec3 centre(1.0f, 2.0f, -3.0f);
  std::vector<glm::vec3> positions;
  for (int i = 0; i < 1001; ++i)
    positions.push_back(centre + glm::vec3(spread(random), spread(random), spread(random)));
  // The exact per-axis median of the cluster.
  glm::vec3 median;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<float> values;
    for (const glm::vec3& p : positions) values.push_back(p[axis]);
    std::sort(values.begin(), values.end());
    median[axis] = values[500];
  }
  EXPECT_EQ(*visibleFocus(positions), median);
  // 40 % more pixels seeing a far wall move the focus by less than the cluster's spread, where
  // a mean would move 40 / 140 of the way (about 11 m) towards the wall.
  for (int i = 0; i < 400; ++i) positions.push_back(glm::vec3(40.0f, 2.0f, -3.0f));
  const glm::vec3 robust = *visibleFocus(positions);
  EXPECT_LT(glm::length(robust - centre), 0.2f);
  EXPECT_GT(glm::length(robust - centre), 0.0f);  // the median did move, slightly
}

TEST(CascadePlacement, DegenerateInputsGiveValidLevels) {
  GridGeometry tiny;
  tiny.origin = glm::vec3(0.0f);
  tiny.cellSize = 1e-6f;
  tiny.resolution = glm::ivec3(1);
  for (const GridGeometry& g :
       placeCascadeLevels(tiny, 8, glm::vec3(1e9f), glm::vec3(0.0f), 1.0f)) {
    EXPECT_TRUE(std::isfinite(g.origin.x) && std::isfinite(g.origin.y) &&
                std::isfinite(g.origin.z));
    EXPECT_GT(g.cellSize, 0.0f);
  }
}

}  // namespace
}  // namespace lpvlab
