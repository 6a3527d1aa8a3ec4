// "trilinear" rendering on the CPU backend (variants/rendering/trilinear_cpu.h), which calls the
// GL kernel's shared functions (shaders/rendering/trilinear_diffuse.glsl, glossy_march.glsl):
//   a. on random grids at SH orders 1-3, with leak damping, a normal offset and a scale, and on
//      a blended three-level cascade, it gives the GL kernel's radiance within float rounding;
//   b. its image does not depend on the thread count;
//   c. "glossy" with a specular albedo gives the GL kernel's radiance, on one level and a cascade.

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "error_support.h"
#include "grid_test_support.h"
#include "rendering_rig.h"

namespace lpvlab {
namespace {

using test::HandGrid;
using test::SurfacePixel;

// Random light (positive band 0, so the reads are mostly light, and random higher bands).
HandGrid randomGrid(const GridGeometry& geometry, int order, std::mt19937& random) {
  HandGrid grid(geometry, order);
  std::uniform_real_distribution<double> band0(0.0, 1.0), rest(-0.4, 0.4);
  grid.fill([&](glm::ivec3, int, std::vector<double>& c) {
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = k == 0 ? band0(random) : rest(random);
  });
  return grid;
}

// Surface points inside `box` (grid coordinates scaled to the world), random normals and albedos.
std::vector<SurfacePixel> randomPixels(const GridGeometry& geometry, int count, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), signedUnit(-1.0, 1.0);
  std::vector<SurfacePixel> pixels;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 g(unit(random) * geometry.resolution.x, unit(random) * geometry.resolution.y,
                       unit(random) * geometry.resolution.z);
    glm::dvec3 n(signedUnit(random), signedUnit(random), signedUnit(random));
    n = glm::length(n) > 1e-3 ? glm::normalize(n) : glm::dvec3(0.0, 1.0, 0.0);
    pixels.push_back({glm::dvec3(geometry.origin) + g * double(geometry.cellSize), n,
                      glm::dvec3(unit(random), unit(random), unit(random))});
  }
  return pixels;
}

double largestDifference(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b,
                         double* scale) {
  double largest = 0.0;
  *scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      largest = std::max(largest, std::abs(a[i][c] - b[i][c]));
      *scale = std::max(*scale, std::abs(b[i][c]));
    }
  return largest;
}

TEST(TrilinearCpu, GivesTheGlKernelsRadianceAtEveryOrderWithItsOptions) {
  std::mt19937 random(17);
  const GridGeometry geometry{glm::vec3(-0.5f, 0.25f, 1.0f), 0.2f, glm::ivec3(9, 7, 8)};
  const std::vector<SurfacePixel> pixels = randomPixels(geometry, 200, random);
  for (int order = 1; order <= 3; ++order) {
    const HandGrid grid = randomGrid(geometry, order, random);
    for (const toml::table& options :
         {toml::table{}, toml::table{{"leak_damping", 4.0}, {"normal_offset", 0.5}, {"scale", 1.7}}}) {
      const auto gl = test::renderPixels("trilinear", options, {grid}, pixels, glm::vec3(0.0f), 0.0f,
                                         ComputeBackend::Gl);
      const auto cpu = test::renderPixels("trilinear", options, {grid}, pixels, glm::vec3(0.0f),
                                          0.0f, ComputeBackend::Cpu);
      double scale = 0.0;
      const double difference = largestDifference(cpu, gl, &scale);
      ASSERT_GT(scale, 0.0);
      EXPECT_LT(difference, 2e-5 * scale) << "order " << order << ", options " << options;
    }
  }
}

TEST(TrilinearCpu, GivesTheGlKernelsBlendOfACascade) {
  std::mt19937 random(23);
  const glm::ivec3 res(8);
  std::vector<HandGrid> levels;
  for (int level = 0; level < 3; ++level) {
    const float cellSize = 0.1f * float(1 << level);
    const GridGeometry geometry{glm::vec3(-0.5f * cellSize * float(res.x)), cellSize, res};
    levels.push_back(randomGrid(geometry, 2, random));
  }
  const std::vector<SurfacePixel> pixels = randomPixels(levels.back().geometry, 300, random);
  const auto gl = test::renderPixels("trilinear", {}, levels, pixels, glm::vec3(0.0f), 1.5f,
                                     ComputeBackend::Gl);
  const auto cpu = test::renderPixels("trilinear", {}, levels, pixels, glm::vec3(0.0f), 1.5f,
                                      ComputeBackend::Cpu);
  double scale = 0.0;
  const double difference = largestDifference(cpu, gl, &scale);
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(difference, 2e-5 * scale);
}

TEST(TrilinearCpu, TheImageDoesNotDependOnTheThreadCount) {
  std::mt19937 random(29);
  const GridGeometry geometry{glm::vec3(0.0f), 0.25f, glm::ivec3(12)};
  const HandGrid grid = randomGrid(geometry, 1, random);
  const std::vector<SurfacePixel> pixels = randomPixels(geometry, 2000, random);
  const auto all = test::renderPixels("trilinear", {}, {grid}, pixels, glm::vec3(0.0f), 0.0f,
                                      ComputeBackend::Cpu);
  std::vector<glm::dvec3> one;
  {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = test::renderPixels("trilinear", {}, {grid}, pixels, glm::vec3(0.0f), 0.0f,
                             ComputeBackend::Cpu);
  }
  EXPECT_EQ(all, one);
}

// "glossy" marches the grid along the reflected view direction (glossy_march.glsl) on both
// backends: the same radiance within float rounding at orders 1-3, on one level and on a blended
// three-level cascade (each march sample weighted by its level's cascade weight).
TEST(TrilinearCpu, GlossyGivesTheGlKernelsRadianceOnOneLevelAndACascade) {
  std::mt19937 random(37);
  const toml::table glossy{{"specular_albedo", 0.5}, {"exponent", 8.0}, {"step", 0.7},
                           {"max_distance", 6.0}, {"normal_offset", 0.3}};
  const glm::vec3 camera(0.3f, 2.5f, -1.5f);
  for (int order = 1; order <= 3; ++order) {
    const GridGeometry geometry{glm::vec3(-0.5f, 0.25f, 1.0f), 0.2f, glm::ivec3(9, 7, 8)};
    std::vector<HandGrid> one = {randomGrid(geometry, order, random)};
    std::vector<HandGrid> three;
    for (int level = 0; level < 3; ++level) {
      const float cellSize = 0.1f * float(1 << level);
      three.push_back(randomGrid(GridGeometry{glm::vec3(-0.5f * cellSize * 8.0f), cellSize, glm::ivec3(8)},
                                 order, random));
    }
    for (const std::vector<HandGrid>* levels : {&one, &three}) {
      const std::vector<SurfacePixel> pixels = randomPixels(levels->back().geometry, 150, random);
      const auto gl = test::renderPixels("glossy", glossy, *levels, pixels, camera, 1.5f,
                                         ComputeBackend::Gl);
      const auto cpu = test::renderPixels("glossy", glossy, *levels, pixels, camera, 1.5f,
                                          ComputeBackend::Cpu);
      const auto diffuse = test::renderPixels("trilinear", toml::table{{"normal_offset", 0.3}}, *levels,
                                              pixels, camera, 1.5f, ComputeBackend::Cpu);
      double scale = 0.0, diffuseScale = 0.0;
      const double difference = largestDifference(cpu, gl, &scale);
      ASSERT_GT(scale, 0.0);
      EXPECT_GT(largestDifference(cpu, diffuse, &diffuseScale), 0.05 * scale)
          << "the glossy term should be a visible part of the radiance";
      EXPECT_LT(difference, 2e-5 * scale) << "order " << order << ", levels " << levels->size();
    }
  }
}

TEST(TrilinearCpu, EveryRenderingOptionHasACpuKernel) {
  const auto refusal = [](const std::string& type, const toml::table& table) {
    Params params(table, "test", "rendering");
    const auto strategy = Registry<RenderingStrategy>::instance().create(params, type);
    return strategy->cpuRefusal(Requirements{});
  };
  EXPECT_EQ(refusal("trilinear", {}), "");
  EXPECT_EQ(refusal("glossy", {}), "");
  EXPECT_EQ(refusal("glossy", toml::table{{"specular_albedo", 0.5}}), "");
  EXPECT_EQ(refusal("subsurface", {}), "");
}

}  // namespace
}  // namespace lpvlab
