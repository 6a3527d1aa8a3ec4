// The CPU kernels of standard gathering and scattering with the geometry volume
// (variants/propagation/standard_cpu.h's StandardOcclusion):
//   a. float on every CPU instruction set this machine has, and double, against the GLSL kernel
//      of the same method (gather, scatter) with a random GV (some GV cells empty, so the kernel's shortcut for unblocked cells
//      is crossed) at SH orders 1-3, the GV switched on from the second iteration, with and
//      without bounces (random albedo), current and accumulated grids;
//   b. bit-identical results for 1 and 2 threads with the GV and bounces, both methods;
//   c. flux: an isotropic source's step never sends on more than it had, with albedo 1 it sends
//      on all of it through the faces a GV of zeros leaves open, and with a GV of zeros the GV
//      changes nothing (T = 1, nothing to bounce).

#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "framework/math/solid_angle.h"
#include "cpu_comparison.h"
#include "propagation_rig.h"
#include "variants/propagation/standard_cpu.h"

namespace lpvlab {
namespace {

using test::Grid;
using test::maxRelativeDifference;
using test::Propagated;

const double kFar = cubeFaceSolidAngles().farFace;
const double kSide = cubeFaceSolidAngles().sideFace;

// `iterations` CPU steps from `injected` with the GV (and, with `albedo`, its bounces) from
// iteration `firstOccluded` on, by `method`, iterations paired as the strategy runs them.
template <class Real>
Propagated cpuPropagate(const Grid& injected, const glm::ivec3& res, int order, int iterations,
                        const Grid& gv, const Grid* albedo, int firstOccluded,
                        const std::string& isa = "auto", int threads = 0,
                        const std::string& method = "gather") {
  const StandardFaceTable<Real> table = makeStandardFaceTable<Real>(order, kFar, kSide);
  const StandardOcclusion<Real> occlusion =
      makeStandardOcclusion(table, res, gv.data(), albedo ? albedo->data() : nullptr);
  std::vector<Real> current(injected.begin(), injected.end()), next(current.size()),
      accumulated = current;
  for (int i = 0; i < iterations; ++i) {
    standardIterationCpu(
        method == "scatter", table, res, current.data(), next.data(), accumulated.data(), isa,
        threads, i >= firstOccluded ? &occlusion : nullptr, pairedAccumulation(i, iterations));
    std::swap(current, next);
  }
  return {std::vector<double>(current.begin(), current.end()),
          std::vector<double>(accumulated.begin(), accumulated.end())};
}

// A random GV with a third of its cells empty.
Grid sparseRandomGv(const glm::ivec3& gvRes, std::mt19937& random) {
  Grid gv = test::randomGv(gvRes, random);
  const int cells = test::cells(gvRes);
  for (int i = 0; i < cells; i += 3)
    for (int k = 0; k < 4; ++k) gv[std::size_t(k) * cells + i] = 0.0f;
  return gv;
}

void matchesGlsl(bool bounces, const std::string& method) {
  const glm::ivec3 res(9, 6, 7);
  std::mt19937 random(bounces ? 21 : 12);
  for (int order = 1; order <= 3; ++order) {
    toml::table table = test::iterationsTable(3, method);
    table.insert("bounces", bounces);
    test::PropagationRig rig("standard", res, table, order, true);
    const Grid injected = test::randomFloats(rig.floatsPerGrid(), random);
    const Grid gv = sparseRandomGv(res + 1, random);
    const Grid albedo = test::randomAlbedo(res + 1, random);
    rig.load(injected);
    rig.loadGv(gv, 1);
    if (bounces) rig.loadAlbedo(albedo);
    rig.propagate();
    const Grid gpuCurrent = rig.current(), gpuAccumulated = rig.accumulated();
    const Grid* albedoOrNull = bounces ? &albedo : nullptr;
    const std::string what =
        method + ", order " + std::to_string(order) + (bounces ? ", bounces" : "");
    for (const std::string& isa : supportedCpuKernelInstructionSets()) {
      const Propagated cpu =
          cpuPropagate<float>(injected, res, order, 3, gv, albedoOrNull, 1, isa, 0, method);
      EXPECT_LT(maxRelativeDifference(cpu.current, gpuCurrent), 2e-5) << what << ", " << isa;
      EXPECT_LT(maxRelativeDifference(cpu.accumulated, gpuAccumulated), 2e-5) << what << ", " << isa;
    }
    const Propagated cpu =
        cpuPropagate<double>(injected, res, order, 3, gv, albedoOrNull, 1, "auto", 0, method);
    EXPECT_LT(maxRelativeDifference(cpu.current, gpuCurrent), 2e-5) << what << ", double";
    EXPECT_LT(maxRelativeDifference(cpu.accumulated, gpuAccumulated), 2e-5) << what << ", double";
    // The GV made a difference, so the comparison covered it.
    const Propagated open = cpuPropagate<double>(injected, res, order, 3, Grid(gv.size(), 0.0f),
                                                 nullptr, 1);
    EXPECT_GT(maxRelativeDifference(open.current, gpuCurrent), 1e-2) << what;
  }
}

TEST(StandardCpuGv, MatchesTheGlslGatherKernelWithAGv) { matchesGlsl(false, "gather"); }
TEST(StandardCpuGv, MatchesTheGlslGatherKernelWithBounces) { matchesGlsl(true, "gather"); }
TEST(StandardCpuGv, MatchesTheGlslScatterKernelWithAGv) { matchesGlsl(false, "scatter"); }
TEST(StandardCpuGv, MatchesTheGlslScatterKernelWithBounces) { matchesGlsl(true, "scatter"); }

TEST(StandardCpuGv, ResultsDoNotDependOnTheThreadCount) {
  const glm::ivec3 res(16, 16, 16);
  std::mt19937 random(4);
  const Grid injected = test::randomFloats(std::size_t(16 * 16 * 16) * 27, random);
  const Grid gv = sparseRandomGv(res + 1, random), albedo = test::randomAlbedo(res + 1, random);
  for (const std::string method : {"gather", "scatter"}) {
    const Propagated one = cpuPropagate<float>(injected, res, 2, 4, gv, &albedo, 0, "auto", 1, method);
    const Propagated two = cpuPropagate<float>(injected, res, 2, 4, gv, &albedo, 0, "auto", 2, method);
    EXPECT_EQ(one.accumulated, two.accumulated) << method;
  }
}

TEST(StandardCpuGv, AStepNeverSendsOnMoreFluxThanItHad) {
  const glm::ivec3 res(21, 21, 21);
  const Grid source = test::pointSource(res, glm::ivec3(10), true);
  const double injected = test::flux(source, res);
  ASSERT_GT(injected, 0.0);
  const auto fluxAfterOneStep = [&](const Grid& gv, const Grid* albedo) {
    const Propagated p = cpuPropagate<double>(source, res, 1, 1, gv, albedo, 0);
    return test::flux(Grid(p.current.begin(), p.current.end()), res) / injected;
  };
  std::mt19937 random(9);
  const Grid zeros(std::size_t(4) * test::cells(res + 1), 0.0f);
  const Grid white = Grid(std::size_t(4) * test::cells(res + 1), 1.0f);  // rho = 1, weight 1
  // No blocking: all of it, bounces or not.
  EXPECT_NEAR(fluxAfterOneStep(zeros, nullptr), 1.0, 1e-6);
  EXPECT_NEAR(fluxAfterOneStep(zeros, &white), 1.0, 1e-6);
#ifdef LPVLAB_SANITIZED
  const int trials = 2;  // double precision at -O0 under the sanitizers: 25 s a trial
#else
  const int trials = 4;
#endif
  for (int trial = 0; trial < trials; ++trial) {
    const Grid gv = test::randomGv(res + 1, random), albedo = test::randomAlbedo(res + 1, random);
    const double blocked = fluxAfterOneStep(gv, nullptr);
    const double bounced = fluxAfterOneStep(gv, &albedo);
    const double white1 = fluxAfterOneStep(gv, &white);
    EXPECT_LT(blocked, 1.0 - 1e-3) << "trial " << trial;  // the GV blocked some of it
    EXPECT_GE(bounced, blocked - 1e-9) << "trial " << trial;  // bounces only give back
    EXPECT_LE(bounced, white1 + 1e-9) << "trial " << trial;   // albedo <= 1
    // rho = 1 re-emits exactly what was blocked: the lobes integrate to the faces' fluxes.
    EXPECT_NEAR(white1, 1.0, 1e-6) << "trial " << trial;
  }
}

}  // namespace
}  // namespace lpvlab
