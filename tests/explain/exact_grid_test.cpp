// The propagation oracle (framework/explain/exact_grid.h) where its answer is known: a single VPL
// in an empty grid, read by the trilinear rendering kernel (variants/rendering/trilinear_cpu.h) at
// cell centres, against the closed form of a point light seen through the SH-projected cosine;
// and a closed convex box, where visibility from the cells changes nothing, against a wall that
// hides half the cells.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/explain/exact_grid.h"
#include "framework/many_lights/ray_scene.h"
#include "reference/test_scenes.h"
#include "variants/rendering/trilinear_cpu.h"

namespace lpvlab {
namespace {

GridGeometry unitGrid(int cells, float size) {
  GridGeometry g;
  g.origin = glm::vec3(-0.5f * size * cells);
  g.cellSize = size;
  g.resolution = glm::ivec3(cells);
  return g;
}

// A scene of one white material, for quads to be added to.
Scene whiteScene(const std::string& source) {
  Scene scene;
  scene.source = source;
  Material white;
  white.name = "white";
  scene.materials.push_back(white);
  return scene;
}

// The radiance the trilinear kernel gives a white Lambertian point at `p` facing `n`.
glm::vec3 renderedAt(const std::vector<float>& grid, const GridGeometry& geometry, int coefficients,
                     const glm::vec3& p, const glm::vec3& n) {
  HostImage position{1, 1, 1, {glm::vec4(p, 1.0f)}}, normal{1, 1, 1, {glm::vec4(n, 0.0f)}},
      albedo{1, 1, 1, {glm::vec4(1.0f)}}, indirect{1, 1, 1, {glm::vec4(0.0f)}};
  const TrilinearCpuLevel level{grid.data(), geometry};
  TrilinearCpuSettings settings;
  settings.coefficients = coefficients;
  trilinearDiffuseCpu(position, normal, albedo, {&level, 1}, settings, indirect);
  return glm::vec3(indirect.texels[0]);
}

// A point light's irradiance through SH of order 1 and the clamped cosine projected on it:
// E = I / d^2 * (1/4 + cos / 2) (the projected lobe, sh.glsl: z_0 Y_00 + z_1 Y_1 . w terms),
// against the exact I / d^2 * cos. At a cell centre the kernel reads that cell alone.
TEST(ExactGrid, SingleVplThroughTheRenderingKernelMatchesTheClosedForm) {
  const GridGeometry geometry = unitGrid(16, 0.25f);
  const Vpl vpl{glm::vec3(0.0f), glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f)), glm::vec3(3.0f, 2.0f, 1.0f), 1};
  const std::vector<float> grid = exactLightGrid({&vpl, 1}, geometry, 4, nullptr);
  int checked = 0;
  for (const glm::ivec3 cell : {glm::ivec3(8, 13, 8), glm::ivec3(12, 12, 10), glm::ivec3(4, 14, 7),
                                glm::ivec3(9, 11, 2), glm::ivec3(14, 9, 13)}) {
    const glm::vec3 centre = geometry.origin + (glm::vec3(cell) + 0.5f) * geometry.cellSize;
    const glm::vec3 d = centre - vpl.position;
    const float d2 = glm::dot(d, d);
    const glm::vec3 w = d / std::sqrt(d2);
    const float cosVpl = glm::dot(vpl.normal, w);
    ASSERT_GT(cosVpl, 0.0f);
    ASSERT_GT(d2, geometry.cellSize * geometry.cellSize);
    for (const glm::vec3 n : {-w, glm::normalize(-w + glm::vec3(0.3f, 0.0f, -0.2f)), glm::vec3(0, -1, 0)}) {
      const float cosReceiver = glm::dot(-n, w);
      const glm::vec3 intensity = vpl.flux / float(M_PI) * cosVpl;
      const glm::vec3 expected = intensity / d2 * (0.25f + 0.5f * cosReceiver) / float(M_PI);
      const glm::vec3 got = renderedAt(grid, geometry, 4, centre, n);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-4f * expected[c] + 1e-9f);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 15);
}

// Higher orders approach the exact cosine: the order-2 lobe is exact for a point light head-on
// (z_0 Y_00 + z_1 ... + z_2 ... at cos = 1 sums to 1/4 + 1/2 + 5/16 = 1.0625) and order 3 adds
// nothing (z_3 = 0).
TEST(ExactGrid, HigherOrdersProjectThePointLightOnTheirBasis) {
  const GridGeometry geometry = unitGrid(8, 0.5f);
  const Vpl vpl{glm::vec3(0.0f, -1.5f, 0.0f), glm::vec3(0, 1, 0), glm::vec3(1.0f), 1};
  const glm::ivec3 cell(4, 6, 4);
  const glm::vec3 centre = geometry.origin + (glm::vec3(cell) + 0.5f) * geometry.cellSize;
  const glm::vec3 d = centre - vpl.position;
  const float d2 = glm::dot(d, d);
  const glm::vec3 w = d / std::sqrt(d2);
  const float exact = glm::dot(vpl.normal, w) / float(M_PI) / d2 / float(M_PI);  // head-on receiver
  const float order2 = renderedAt(exactLightGrid({&vpl, 1}, geometry, 9, nullptr), geometry, 9, centre, -w).r;
  const float order3 = renderedAt(exactLightGrid({&vpl, 1}, geometry, 16, nullptr), geometry, 16, centre, -w).r;
  EXPECT_NEAR(order2 / exact, 1.0625f, 1e-4f);
  EXPECT_NEAR(order3 / exact, 1.0625f, 1e-4f);
}

// Closer than a cell, the VPL's light is spread over the cell's cross-section (I / s^2), as LPV
// injects it: finite, and continuous with the 1 / d^2 law at d = s.
TEST(ExactGrid, AVplInsideACellIsSpreadOverItsCrossSection) {
  const GridGeometry geometry = unitGrid(4, 1.0f);
  const glm::vec3 centre(0.5f);
  for (const float distance : {1e-6f, 0.3f, 0.99f, 1.0f}) {
    const Vpl vpl{centre - glm::vec3(0, distance, 0), glm::vec3(0, 1, 0), glm::vec3(1.0f), 1};
    const std::vector<float> grid = exactLightGrid({&vpl, 1}, geometry, 4, nullptr);
    const int index = 2 + 4 * (2 + 4 * 2);
    const float c0 = grid[std::size_t(index)];  // channel 0, coefficient 0
    EXPECT_TRUE(std::isfinite(c0));
    EXPECT_NEAR(c0, 1.0f / float(M_PI) * 0.5f / std::sqrt(float(M_PI)), 1e-5f) << distance;
  }
}

// A closed convex box: every VPL on its inner walls sees every cell centre inside it, so the grid
// with visibility is the grid without. A wall across the middle then hides the far half.
TEST(ExactGrid, VisibilityChangesNothingInAConvexBoxAndHidesBehindAWall) {
  Scene scene = whiteScene("test:box");
  const float a = 1.0f;
  const auto wall = [&](const char* name, std::array<glm::vec3, 4> corners) {
    scene.meshes.push_back(testing::quad(name, 0, corners));
  };
  // Six faces, normals inwards.
  wall("floor", {glm::vec3(-a, -a, -a), glm::vec3(-a, -a, a), glm::vec3(a, -a, a), glm::vec3(a, -a, -a)});
  wall("ceiling", {glm::vec3(-a, a, -a), glm::vec3(a, a, -a), glm::vec3(a, a, a), glm::vec3(-a, a, a)});
  wall("left", {glm::vec3(-a, -a, -a), glm::vec3(-a, a, -a), glm::vec3(-a, a, a), glm::vec3(-a, -a, a)});
  wall("right", {glm::vec3(a, -a, -a), glm::vec3(a, -a, a), glm::vec3(a, a, a), glm::vec3(a, a, -a)});
  wall("back", {glm::vec3(-a, -a, -a), glm::vec3(a, -a, -a), glm::vec3(a, a, -a), glm::vec3(-a, a, -a)});
  wall("front", {glm::vec3(-a, -a, a), glm::vec3(-a, a, a), glm::vec3(a, a, a), glm::vec3(a, -a, a)});
  std::vector<Vpl> vpls;
  for (int i = 0; i < 6; ++i) {
    const float u = -0.8f + 0.3f * i;
    vpls.push_back({glm::vec3(u, -a, 0.5f * u), glm::vec3(0, 1, 0), glm::vec3(1.0f, 0.5f, 0.2f), 1});
    vpls.push_back({glm::vec3(-a, 0.4f * u, u), glm::vec3(1, 0, 0), glm::vec3(0.2f, 0.5f, 1.0f), 1});
  }
  const GridGeometry geometry = unitGrid(8, 0.25f);  // exactly the box's inside
  {
    const RayScene rays(scene);
    const std::vector<float> open = exactLightGrid(vpls, geometry, 4, nullptr);
    const std::vector<float> visible = exactLightGrid(vpls, geometry, 4, &rays.embree());
    ASSERT_EQ(open.size(), visible.size());
    double total = 0.0;
    for (std::size_t i = 0; i < open.size(); ++i) {
      EXPECT_EQ(visible[i], open[i]) << i;
      total += std::abs(open[i]);
    }
    EXPECT_GT(total, 0.0);
  }
  // A wall at x = 0 (both sides, on a boundary between cells), between the VPLs at x < 0 on the
  // floor and the left wall and the cells beyond it, whose every visibility point it hides.
  wall("divider", {glm::vec3(0.0f, -a, -a), glm::vec3(0.0f, -a, a), glm::vec3(0.0f, a, a), glm::vec3(0.0f, a, -a)});
  wall("divider back", {glm::vec3(0.0f, -a, -a), glm::vec3(0.0f, a, -a), glm::vec3(0.0f, a, a), glm::vec3(0.0f, -a, a)});
  std::vector<Vpl> left;
  for (const Vpl& vpl : vpls)
    if (vpl.position.x < 0.0f) left.push_back(vpl);
  const RayScene rays(scene);
  const std::vector<float> open = exactLightGrid(left, geometry, 4, nullptr);
  const std::vector<float> visible = exactLightGrid(left, geometry, 4, &rays.embree());
  const int cells = geometry.cellCount();
  int hidden = 0, seen = 0;
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        const int cell = x + 8 * (y + 8 * z);
        const float centreX = geometry.origin.x + (x + 0.5f) * geometry.cellSize;
        for (int k = 0; k < 12; ++k) {
          const std::size_t i = std::size_t(k) * cells + cell;  // channel-major, as grid.glsl
          if (centreX > 0.0f) {
            EXPECT_EQ(visible[i], 0.0f);
            hidden += open[i] != 0.0f;
          } else {
            EXPECT_EQ(visible[i], open[i]);
            seen += open[i] != 0.0f;
          }
        }
      }
  EXPECT_GT(hidden, 100);
  EXPECT_GT(seen, 100);
}

TEST(ExactGrid, RefusesACoefficientCountTheBasisLacks) {
  const Vpl vpl{glm::vec3(0.0f), glm::vec3(0, 1, 0), glm::vec3(1.0f), 1};
  EXPECT_THROW(exactLightGrid({&vpl, 1}, unitGrid(2, 1.0f), 5, nullptr), Error);
}

}  // namespace
}  // namespace lpvlab

namespace lpvlab {
namespace {

// A cell the wall cuts through sees the VPL from half its visibility points: half the light.
TEST(ExactGrid, ACellAWallCutsSeesTheLightFromItsOpenPart) {
  Scene scene = whiteScene("test:wall");
  // The plane z = 0 facing +z and -z, far wider than the grid.
  scene.meshes.push_back(testing::quad("wall", 0, {glm::vec3(-9, -9, 0), glm::vec3(9, -9, 0), glm::vec3(9, 9, 0), glm::vec3(-9, 9, 0)}));
  scene.meshes.push_back(testing::quad("back", 0, {glm::vec3(-9, -9, 0), glm::vec3(-9, 9, 0), glm::vec3(9, 9, 0), glm::vec3(9, -9, 0)}));
  GridGeometry geometry;
  geometry.origin = glm::vec3(-0.5f);
  geometry.cellSize = 1.0f;
  geometry.resolution = glm::ivec3(1);  // one cell, centred on the wall
  const Vpl vpl{glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0, 0, -1), glm::vec3(1.0f), 1};
  const RayScene rays(scene);
  const std::vector<float> open = exactLightGrid({&vpl, 1}, geometry, 4, nullptr);
  const std::vector<float> visible = exactLightGrid({&vpl, 1}, geometry, 4, &rays.embree());
  EXPECT_GT(open[0], 0.0f);
  EXPECT_FLOAT_EQ(visible[0], 0.5f * open[0]);
}

}  // namespace
}  // namespace lpvlab
