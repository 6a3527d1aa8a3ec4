// The CPU kernel of standard gathering (variants/propagation/standard_cpu.h):
//   a. float on every CPU instruction set this machine has, and double, against the GLSL gather
//      kernel on random grids (positive and negative coefficients, so the clamp acts) at SH
//      orders 1-3 on a non-cubic grid, over several iterations, current and accumulated grids;
//   b. the double kernel against the double-precision C++ of the shared GLSL, called per cell
//      and face directly (standard_faces.glsl's propagateToNeighbour at order 1);
//   c. bit-identical results for 1 and 2 threads (no atomics, fixed order of additions);
//   d. flux: an isotropic source sends its whole flux on in one step (the 30 faces tile the
//      sphere);
//   e. scattering (six passes, one per direction) against the GLSL scatter kernel and the CPU
//      gather, at every order and instruction set;
//   f. bad instruction sets and extreme grids (1 cell, 1 x 1 x N) are errors or stay finite.

#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "error_support.h"
#include "framework/math/solid_angle.h"
#include "cpu_comparison.h"
#include "propagation_rig.h"
#include "variants/propagation/standard_cpu.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/standard_faces.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using test::Grid;
using test::maxRelativeDifference;

const double kFar = cubeFaceSolidAngles().farFace;
const double kSide = cubeFaceSolidAngles().sideFace;

template <class Real>
std::vector<Real> as(const Grid& g) {
  return std::vector<Real>(g.begin(), g.end());
}

// `iterations` CPU steps from `injected`: {current, accumulated}.
template <class Real>
std::pair<std::vector<Real>, std::vector<Real>> cpuPropagate(const Grid& injected,
                                                             const glm::ivec3& res, int order,
                                                             int iterations,
                                                             const std::string& isa = "auto",
                                                             int threads = 0) {
  const StandardFaceTable<Real> table = makeStandardFaceTable<Real>(order, kFar, kSide);
  std::vector<Real> current = as<Real>(injected), next(current.size()), accumulated = current;
  for (int i = 0; i < iterations; ++i) {
    standardGatherCpu(table, res, current.data(), next.data(), accumulated.data(), isa, threads);
    std::swap(current, next);
  }
  return {current, accumulated};
}

TEST(StandardCpu, MatchesTheGlslGatherKernelAtEveryOrderAndInstructionSet) {
  const glm::ivec3 res(9, 6, 7);
  std::mt19937 random(5);
  for (int order = 1; order <= 3; ++order) {
    test::PropagationRig rig("standard", res, test::iterationsTable(3), order);
    const Grid injected = test::randomFloats(rig.floatsPerGrid(), random);
    rig.load(injected);
    rig.propagate();
    const Grid gpuCurrent = rig.current(), gpuAccumulated = rig.accumulated();
    for (const std::string& isa : supportedCpuKernelInstructionSets()) {
      const auto [current, accumulated] = cpuPropagate<float>(injected, res, order, 3, isa);
      EXPECT_LT(maxRelativeDifference(current, gpuCurrent), 2e-5) << "order " << order << ", " << isa;
      EXPECT_LT(maxRelativeDifference(accumulated, gpuAccumulated), 2e-5) << "order " << order << ", " << isa;
    }
    const auto [current, accumulated] = cpuPropagate<double>(injected, res, order, 3);
    EXPECT_LT(maxRelativeDifference(current, gpuCurrent), 2e-5) << "order " << order << ", double";
    EXPECT_LT(maxRelativeDifference(accumulated, gpuAccumulated), 2e-5) << "order " << order;
  }
}

TEST(StandardCpu, ScatterMatchesTheGlslScatterKernelAndTheGather) {
  const glm::ivec3 res(9, 6, 7);
  std::mt19937 random(15);
  for (int order = 1; order <= 3; ++order) {
    test::PropagationRig rig("standard", res, test::iterationsTable(3, "scatter"), order);
    const Grid injected = test::randomFloats(rig.floatsPerGrid(), random);
    rig.load(injected);
    rig.propagate();
    const Grid gpuCurrent = rig.current(), gpuAccumulated = rig.accumulated();
    const auto [gatherCurrent, gatherAccumulated] = cpuPropagate<double>(injected, res, order, 3);
    const Grid gathered(gatherAccumulated.begin(), gatherAccumulated.end());
    const StandardFaceTable<float> table = makeStandardFaceTable<float>(order, kFar, kSide);
    for (const std::string& isa : supportedCpuKernelInstructionSets()) {
      std::vector<float> current(injected.begin(), injected.end()), next(current.size()),
          accumulated = current;
      for (int i = 0; i < 3; ++i) {
        standardScatterCpu(table, res, current.data(), next.data(), accumulated.data(), isa);
        std::swap(current, next);
      }
      EXPECT_LT(maxRelativeDifference(current, gpuCurrent), 2e-5) << "order " << order << ", " << isa;
      EXPECT_LT(maxRelativeDifference(accumulated, gpuAccumulated), 2e-5) << "order " << order << ", " << isa;
      EXPECT_LT(maxRelativeDifference(accumulated, gathered), 2e-5) << "order " << order << ", " << isa;
    }
  }
}

// Pairing iterations (the accumulated grid updated every other one, StepAccumulation) gives
// the sum of adding every iteration, for an even and an odd count, gathering and scattering.
TEST(StandardCpu, PairedIterationsAccumulateTheSameSum) {
  const glm::ivec3 res(11, 7, 9);
  std::mt19937 random(23);
  const StandardFaceTable<double> table = makeStandardFaceTable<double>(2, kFar, kSide);
  const Grid injected = test::randomFloats(std::size_t(res.x * res.y * res.z) * 27, random);
  for (const bool scatter : {false, true})
    for (const int iterations : {4, 5}) {
      std::vector<double> sums[2];
      for (const bool paired : {false, true}) {
        std::vector<double> current(injected.begin(), injected.end()), next(current.size()),
            accumulated = current;
        for (int i = 0; i < iterations; ++i) {
          standardIterationCpu(
              scatter, table, res, current.data(), next.data(), accumulated.data(), "auto", 0,
              nullptr, paired ? pairedAccumulation(i, iterations) : StepAccumulation::Target);
          std::swap(current, next);
        }
        sums[paired] = accumulated;
      }
      double largest = 0.0, scale = 0.0;
      for (std::size_t i = 0; i < sums[0].size(); ++i) {
        largest = std::max(largest, std::abs(sums[0][i] - sums[1][i]));
        scale = std::max(scale, std::abs(sums[0][i]));
      }
      EXPECT_LT(largest, 1e-12 * scale) << (scatter ? "scatter, " : "gather, ") << iterations;
      EXPECT_GT(scale, 0.0);
    }
}

TEST(StandardCpu, DoubleKernelIsTheSharedTransferCellByCell) {
  const glm::ivec3 res(5, 4, 3);
  std::mt19937 random(8);
  const Grid injected = test::randomFloats(std::size_t(res.x * res.y * res.z) * 12, random);
  const auto [current, accumulated] = cpuPropagate<double>(injected, res, 1, 1);
  for (int z = 0; z < res.z; ++z)
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        for (int channel = 0; channel < 3; ++channel) {
          glm::dvec4 expected(0.0);
          for (int axis = 0; axis < 3; ++axis)
            for (int sign : {-1, 1}) {
              glm::ivec3 offset(0);
              offset[axis] = sign;
              const glm::ivec3 from = cell + offset;
              if (glm::any(glm::lessThan(from, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(from, res)))
                continue;
              expected += shared::propagateToNeighbour(test::cellOf(injected, res, from, channel),
                                                       -glm::dvec3(offset), kFar, kSide);
            }
          const int cells = res.x * res.y * res.z, index = x + res.x * (y + res.y * z);
          for (int k = 0; k < 4; ++k)
            ASSERT_NEAR(current[(channel * 4 + k) * cells + index], expected[k], 1e-12)
                << "cell " << x << "," << y << "," << z << " channel " << channel << " k " << k;
        }
      }
}

TEST(StandardCpu, ResultsDoNotDependOnTheThreadCount) {
  const glm::ivec3 res(16, 16, 16);
  std::mt19937 random(3);
  const Grid injected = test::randomFloats(std::size_t(16 * 16 * 16) * 27, random);
  const auto one = cpuPropagate<float>(injected, res, 2, 4, "auto", 1);
  const auto two = cpuPropagate<float>(injected, res, 2, 4, "auto", 2);
  EXPECT_EQ(std::memcmp(one.second.data(), two.second.data(), one.second.size() * sizeof(float)), 0);
}

TEST(StandardCpu, AnIsotropicSourceSendsOnItsWholeFlux) {
  // Flux of a cell: the integral of its intensity, 4 pi * Y0 * c0 (band 0 only).
  const glm::ivec3 res(21, 21, 21);
  const Grid source = test::pointSource(res, glm::ivec3(10), true);
  const double injected = test::flux(source, res);
  ASSERT_GT(injected, 0.0);
  // After one step all the light sits in the 6 neighbours: the faces tile the sphere, and the
  // clamp never acts on an isotropic source.
  const auto [current, accumulated] = cpuPropagate<double>(source, res, 1, 1);
  const Grid afterOne(current.begin(), current.end());
  EXPECT_NEAR(test::flux(afterOne, res) / injected, 1.0, 1e-6);  // float storage
}

// The kernel skips the SH products that vanish on axis-aligned faces, decided when it is
// compiled: the multiply-adds it counts must be the tables' non-zero entries (the faces' and the
// lobes'), computed independently from the shared GLSL, at every order. The one exception, kept
// on purpose: at order 3, Y11 and Y13 carry a factor 5z^2 - 1, which is zero on the 8 side faces
// whose direction (2, 0, 1) / sqrt(5) has z^2 = 1/5; that zero is a coincidence of rounding-free
// arithmetic, too fragile to skip (a skipped product must be exactly zero).
TEST(StandardCpu, TheKernelSkipsExactlyTheTablesZeros) {
  for (int order = 1; order <= 3; ++order) {
    const auto table = makeStandardFaceTable<double>(order, kFar, kSide);
    int nonZero = 0;
    for (int normal = 0; normal < 6; ++normal)
      for (int k = 0; k < table.coefficients; ++k) {
        nonZero += table.normalLobe[normal][k] != 0.0 ? 1 : 0;
        for (int direction = 0; direction < 6; ++direction)
          nonZero += table.scaledBasis[direction][normal][k] != 0.0 ? 1 : 0;
      }
    EXPECT_EQ(standardGatherMultiplyAdds(table.coefficients), nonZero + (order == 3 ? 8 : 0))
        << "order " << order;
    EXPECT_LT(nonZero, 36 * table.coefficients) << "order " << order;  // something is skipped
  }
}

TEST(StandardCpu, BadSettingsAreErrorsAndTinyGridsStayFinite) {
  std::vector<float> one(12, 1.0f), next(12), accumulated(12);
  const auto table = makeStandardFaceTable<float>(1, kFar, kSide);
  EXPECT_TRUE(test::contains(test::errorOf([&] {
    standardGatherCpu(table, glm::ivec3(1), one.data(), next.data(), accumulated.data(), "avx9");
  }), "'avx9' is not one of"));
  EXPECT_TRUE(test::contains(test::errorOf([&] { makeStandardFaceTable<float>(4, kFar, kSide); }),
                             "SH order 4"));
  EXPECT_TRUE(test::contains(test::errorOf([&] { makeStandardFaceTable<float>(1, NAN, kSide); }),
                             "solid angle"));
  // One cell: nothing to gather from, so it empties.
  standardGatherCpu(table, glm::ivec3(1), one.data(), next.data(), accumulated.data());
  for (float v : next) EXPECT_EQ(v, 0.0f);
  // A 1 x 1 x 40 column for 1000 iterations, from very bright light: finite throughout.
  const glm::ivec3 column(1, 1, 40);
  Grid bright(std::size_t(40) * 12, 0.0f);
  bright[20] = 1e30f;
  const auto [current, total] = cpuPropagate<float>(bright, column, 1, 1000);
  for (float v : total) ASSERT_TRUE(std::isfinite(v));
}

}  // namespace
}  // namespace lpvlab
