// The CPU backend's per-pixel and per-texel kernels run the shared GLSL in single precision, as
// GL does, compiled for each instruction-set level (framework/core/cpu_dispatch.h). Here each is
// checked, at every level this CPU runs, against the same shared functions compiled in double
// precision in this file, on random inputs:
//   a. direct light (direct_lighting_cpu.h): a spot, a point and a directional light over random
//      surface points, with random shadow maps;
//   b. trilinear rendering (trilinear_cpu.h): random grids at SH orders 1-3, with and without leak
//      damping; the reference reads the grid in its GL layout (grid.glsl), not the kernel's copy
//      laid out cell by cell;
//   c. RSM injection (rsm_vpl_cpu.h): random VPLs, summed per cell in double precision here.
// Each agrees within float rounding: 1e-4 of the largest value (a wrong texel, cell, coefficient
// or weight is off by the order of the values themselves).

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/cpu_dispatch.h"
#include "framework/math/shared.h"
#include "framework/pipeline/direct_lighting_cpu.h"
#include "variants/injection/rsm_vpl_cpu.h"
#include "variants/rendering/trilinear_cpu.h"

// The shared functions in double precision: the direct light's reads, trilinear rendering's over
// the GL layout of `referenceGrid`, and the VPL's cell and lobe.
LPVLAB_SHARED_GLSL_BEGIN
#include "framework/pipeline/direct_light_kernel.h"
const float* referenceGrid = nullptr;
real gridCoefficient(int channel, int k, int coefficients, int cell, int cells) {
  return real(referenceGrid[coefficientIndex(channel, k, coefficients, cell, cells)]);
}
#include "shaders/rendering/trilinear_diffuse.glsl"
#include "shaders/injection/vpl.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using glm::dvec3;

// Largest |a - b| over the largest |b|, over every value.
template <class A, class B>
double relativeLargestDifference(const std::vector<A>& a, const std::vector<B>& b) {
  double largest = 0.0, difference = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    largest = std::max(largest, std::abs(double(b[i])));
    difference = std::max(difference, std::abs(double(a[i]) - double(b[i])));
  }
  return largest > 0.0 ? difference / largest : difference;
}

std::vector<double> rgbOf(const HostImage& image) {
  std::vector<double> values;
  for (const glm::vec4& t : image.texels) values.insert(values.end(), {t.x, t.y, t.z});
  return values;
}

std::vector<double> rgbOf(const std::vector<dvec3>& image) {
  std::vector<double> values;
  for (const dvec3& t : image) values.insert(values.end(), {t.x, t.y, t.z});
  return values;
}

constexpr double kFloatTolerance = 1e-4;

TEST(CpuKernelPrecision, DirectLightAgreesWithDoublePrecisionAtEveryLevel) {
  constexpr int kSize = 64, kShadow = 128;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Bounds box;
  box.extend(glm::vec3(0.0f));
  box.extend(glm::vec3(1.0f));
  Light spot, point, sun;
  spot.type = LightType::Spot;
  spot.position = {0.5f, 0.95f, 0.5f};
  spot.outerConeAngle = 1.0f;
  spot.innerConeAngle = 0.5f;
  point.position = {0.3f, 0.6f, 0.7f};
  point.intensity = 2.0f;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  const LightViews records = buildLightViews({spot, point, sun}, box);

  // Random surface points in the box (some pixels without a surface), random normals; shadow
  // maps whose 8x8 blocks hold a near occluder or nothing, so taps straddle their edges.
  HostImage position{kSize, kSize, 1, {}}, normal = position, albedo = position, emission = position;
  for (int i = 0; i < kSize * kSize; ++i) {
    const bool covered = unit(random) < 0.9f;
    position.texels.emplace_back(unit(random), unit(random), unit(random), covered ? 1.0f : 0.0f);
    normal.texels.emplace_back(glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) -
                                              0.5f + glm::vec3(0.0f, 0.01f, 0.0f)), 0.0f);
    albedo.texels.emplace_back(unit(random), unit(random), unit(random), 1.0f);
    emission.texels.emplace_back(unit(random) < 0.1f ? glm::vec3(0.2f) : glm::vec3(0.0f), 0.0f);
  }
  HostDepthImage shadow{kShadow, kShadow, int(records.views.size()), {}};
  std::vector<float> blockDepth;
  for (int b = 0; b < shadow.layers * (kShadow / 8) * (kShadow / 8); ++b)
    blockDepth.push_back(unit(random) < 0.5f ? 0.2f * unit(random) : 2.0f);
  for (int layer = 0; layer < shadow.layers; ++layer)
    for (int y = 0; y < kShadow; ++y)
      for (int x = 0; x < kShadow; ++x)
        shadow.depths.push_back(blockDepth[std::size_t((layer * (kShadow / 8) + y / 8) * (kShadow / 8) + x / 8)]);

  // The reference: direct_light.glsl in double precision, pixel by pixel.
  const auto [lights, views] = sharedLightViews<shared::GpuLight, shared::GpuView>(records);
  shared::DirectLightKernel reference{lights.data(), views.data(), shadow.depths.data(), kShadow};
  std::vector<dvec3> expected;
  for (int i = 0; i < kSize * kSize; ++i)
    expected.push_back(position.texels[std::size_t(i)].w == 0.0f
                           ? dvec3(0.0)
                           : reference.directRadiance(dvec3(position.texels[std::size_t(i)]),
                                                      dvec3(normal.texels[std::size_t(i)]),
                                                      dvec3(albedo.texels[std::size_t(i)]),
                                                      dvec3(emission.texels[std::size_t(i)]),
                                                      int(lights.size()), kShadow, 1.5, 2e-5));
  double lit = 0.0;
  for (const dvec3& v : expected) lit += v.x > 0.0 ? 1.0 : 0.0;
  ASSERT_GT(lit, 0.3 * kSize * kSize) << "the test's lights should reach most pixels";

  for (const CpuKernelLevel level : cpuKernelLevelsThisCpuRuns()) {
    HostImage out{kSize, kSize, 1, std::vector<glm::vec4>(std::size_t(kSize) * kSize)};
    directLightingCpu({.position = &position, .normal = &normal, .albedo = &albedo,
                       .emission = &emission, .shadowDepth = &shadow, .records = &records,
                       .normalOffsetTexels = 1.5f, .depthBias = 2e-5f, .instructions = level},
                      out);
    EXPECT_LT(relativeLargestDifference(rgbOf(out), rgbOf(expected)), kFloatTolerance)
        << cpuKernelLevelName(level);
  }
}

TEST(CpuKernelPrecision, TrilinearRenderingAgreesWithDoublePrecisionAtEveryLevel) {
  constexpr int kPixels = 2000;
  const glm::ivec3 resolution(6, 5, 7);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  GridGeometry geometry;
  geometry.resolution = resolution;
  geometry.cellSize = 0.25f;
  geometry.origin = {-0.5f, 0.25f, 1.0f};
  // Points anywhere in the grid and a cell beyond it (reads clamp at the edge).
  HostImage position{kPixels, 1, 1, {}}, normal = position, albedo = position;
  for (int i = 0; i < kPixels; ++i) {
    const glm::vec3 g = glm::vec3(unit(random), unit(random), unit(random)) *
                            (glm::vec3(resolution) + 2.0f) - 1.0f;
    position.texels.emplace_back(geometry.origin + g * geometry.cellSize, 1.0f);
    normal.texels.emplace_back(glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) -
                                              0.5f + glm::vec3(0.01f)), 0.0f);
    albedo.texels.emplace_back(unit(random), unit(random), unit(random), 1.0f);
  }
  for (const int order : {1, 2, 3}) {
    const int n = (order + 1) * (order + 1);
    std::vector<float> grid(std::size_t(geometry.cellCount()) * 3 * n);
    // Mostly positive intensity, as light is, with signed higher coefficients.
    for (std::size_t i = 0; i < grid.size(); ++i) grid[i] = unit(random) - (i % n == 0 ? 0.0f : 0.5f);
    shared::referenceGrid = grid.data();
    for (const float leakDamping : {0.0f, 2.0f}) {
      std::vector<dvec3> expected;
      for (int i = 0; i < kPixels; ++i)
        expected.push_back(shared::trilinearDiffuse(
            dvec3(position.texels[std::size_t(i)]), dvec3(normal.texels[std::size_t(i)]),
            dvec3(albedo.texels[std::size_t(i)]), dvec3(geometry.origin), double(geometry.cellSize),
            resolution, n, 0.5, double(leakDamping)));
      for (const CpuKernelLevel level : cpuKernelLevelsThisCpuRuns()) {
        HostImage out{kPixels, 1, 1, std::vector<glm::vec4>(kPixels, glm::vec4(0.0f))};
        const TrilinearCpuLevel levels[] = {{grid.data(), geometry}};
        trilinearDiffuseCpu(position, normal, albedo, levels,
                            {.coefficients = n, .normalOffsetCells = 0.5f,
                             .leakDamping = leakDamping, .instructions = level},
                            out);
        EXPECT_LT(relativeLargestDifference(rgbOf(out), rgbOf(expected)), kFloatTolerance)
            << cpuKernelLevelName(level) << ", order " << order << ", leak damping " << leakDamping;
        for (const glm::vec4& t : out.texels) ASSERT_EQ(t.w, 1.0f);  // one level: weight 1
      }
    }
  }
  shared::referenceGrid = nullptr;
}

TEST(CpuKernelPrecision, RsmInjectionAgreesWithDoublePrecisionAtEveryLevel) {
  constexpr int kSize = 48, kLayers = 3;
  constexpr float kShift = 1.0f;
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  GridGeometry grid;
  grid.resolution = {8, 6, 7};
  grid.cellSize = 0.5f;
  grid.origin = {1.0f, -2.0f, 0.5f};
  // Each VPL lands, once shifted along its normal, within 0.3 cells of a cell's centre (no cell
  // boundary for float and double rounding to disagree on); a tenth of the texels is uncovered.
  const std::size_t texels = std::size_t(kSize) * kSize * kLayers;
  HostImage position{kSize, kSize, kLayers, {}}, normal = position, flux = position;
  for (std::size_t t = 0; t < texels; ++t) {
    const glm::vec3 n = glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) - 0.5f +
                                       glm::vec3(0.01f));
    const glm::vec3 cell = glm::floor(glm::vec3(unit(random), unit(random), unit(random)) *
                                      glm::vec3(grid.resolution));
    const glm::vec3 g = cell + 0.5f + 0.6f * (glm::vec3(unit(random), unit(random), unit(random)) - 0.5f);
    position.texels.emplace_back(grid.origin + g * grid.cellSize - n * (kShift * grid.cellSize), 1.0f);
    normal.texels.emplace_back(n, 0.0f);
    flux.texels.emplace_back(unit(random), unit(random), unit(random), unit(random) < 0.9f ? 1.0f : 0.0f);
  }
  for (const int order : {1, 2, 3}) {
    const int n = (order + 1) * (order + 1), cells = grid.cellCount();
    std::vector<double> expected(std::size_t(cells) * 3 * n, 0.0), expectedNormals(std::size_t(cells) * 4, 0.0);
    for (std::size_t t = 0; t < texels; ++t) {
      if (flux.texels[t].w == 0.0f) continue;
      const glm::ivec3 c = shared::vplCell(dvec3(position.texels[t]), dvec3(normal.texels[t]),
                                           dvec3(grid.origin), double(grid.cellSize), double(kShift));
      ASSERT_TRUE(shared::cellInside(c, grid.resolution));
      const int cell = shared::cellIndex(c, grid.resolution);
      const dvec3 phi(flux.texels[t]), nd(normal.texels[t]);
      for (int k = 0; k < n; ++k)
        for (int channel = 0; channel < 3; ++channel)
          expected[std::size_t(shared::coefficientIndex(channel, k, n, cell, cells))] +=
              phi[channel] * shared::vplLobeAt(k, nd);
      const double weight = phi.x + phi.y + phi.z;
      for (int a = 0; a < 3; ++a) expectedNormals[std::size_t(cell) * 4 + a] += weight * nd[a];
      expectedNormals[std::size_t(cell) * 4 + 3] += weight;
    }
    for (const CpuKernelLevel level : cpuKernelLevelsThisCpuRuns()) {
      std::vector<float> coefficients(expected.size(), 0.0f), normals(expectedNormals.size(), 0.0f);
      injectRsmVplsCpu({&position, &normal, &flux}, grid, n, kShift, coefficients.data(),
                       normals.data(), level);
      EXPECT_LT(relativeLargestDifference(coefficients, expected), kFloatTolerance)
          << cpuKernelLevelName(level) << ", order " << order;
      EXPECT_LT(relativeLargestDifference(normals, expectedNormals), kFloatTolerance)
          << cpuKernelLevelName(level) << ", order " << order;
    }
  }
}

}  // namespace
}  // namespace lpvlab
