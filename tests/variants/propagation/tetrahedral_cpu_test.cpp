// Tetrahedral propagation's CPU kernels (variants/propagation/tetrahedral_cpu.h):
//   a. split, steps and merge in float on every CPU instruction set this machine has, and in
//      double, against the GLSL kernels over five steps of random light, SH orders 1-3, both
//      face-flux rules, with and without a random geometry volume (its first three steps
//      unoccluded, as tetFirstOccludedStep(1) says; a slab of it empty, where the kernel skips the
//      faces of cells that see only empty GV cells), current and accumulated grids;
//   b. the strategy on the CPU backend finds its GV's faces again when the GV changes;
//   c. results do not depend on the thread count.
// The kernels' tests against the double-precision C++ model, flux, symmetry and the GV walls run
// on both backends in tetrahedral_test.cpp.

#include "variants/propagation/tetrahedral_cpu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "cpu_comparison.h"
#include "framework/core/cpu_features.h"
#include "variants/resources/geometry_volume.h"
#include "propagation_rig.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using test::Grid;
using test::maxRelativeDifference;
using test::Propagated;

template <class Real>
Propagated cpuPropagate(const Grid& current, const Grid& accumulated, const glm::ivec3& res,
                        int order, bool integrals, int steps, const Grid* gv, CpuKernelLevel level,
                        int threads = 0) {
  const TetrahedralTable<Real> table = makeTetrahedralTable<Real>(order, integrals);
  TetrahedralLattice<Real> lattice(res, table.coefficients);
  TetrahedralOcclusion<Real> occlusion;
  if (gv) occlusion = makeTetrahedralOcclusion(lattice, gv->data());
  std::vector<Real> cubes(current.begin(), current.end()),
      sum(accumulated.begin(), accumulated.end());
  tetrahedralSplitCpu(cubes.data(), lattice);
  const int firstOccluded = shared::tetFirstOccludedStep(1);
  for (int i = 0; i < steps; ++i)
    tetrahedralStepCpu(table, lattice, gv && i >= firstOccluded ? &occlusion : nullptr, level,
                       pairedAccumulation(i, steps), threads);
  tetrahedralMergeCpu(lattice, cubes.data(), sum.data());
  return {std::vector<double>(cubes.begin(), cubes.end()),
          std::vector<double>(sum.begin(), sum.end())};
}

// The GV with its cells x < `x` emptied: the cubes x = 0 see only empty GV cells (the kernel
// skips their faces: T = 1), the cube x = 1 both kinds.
Grid emptyBelow(Grid gv, const glm::ivec3& gvRes, int x) {
  const int cells = shared::cellCount(gvRes);
  test::forEachCell(gvRes, [&](const glm::ivec3& c) {
    if (c.x >= x) return;
    for (int k = 0; k < 4; ++k) gv[std::size_t(k) * cells + shared::cellIndex(c, gvRes)] = 0.0f;
  });
  return gv;
}

void matchesGlsl(bool withGv) {
  const glm::ivec3 res(7, 5, 6);
  const int steps = 5;
  std::mt19937 random(withGv ? 77 : 7);
  for (int order = 1; order <= 3; ++order)
    for (const bool integrals : {true, false}) {
      toml::table table = test::iterationsTable(steps);
      table.insert("face_flux", integrals ? "integral" : "centre");
      test::PropagationRig rig("tetrahedral", res, table, order, withGv);
      const Grid current = test::randomFloats(rig.floatsPerGrid(), random);
      const Grid accumulated = test::randomFloats(rig.floatsPerGrid(), random);
      const Grid gv = emptyBelow(test::randomBlocking(shared::cellCount(res + 1), random), res + 1, 3);
      rig.load(current, accumulated);
      if (withGv) rig.loadGv(gv, 1);
      rig.propagate();
      const Grid glCurrent = rig.current(), glAccumulated = rig.accumulated();
      const Grid* gvOrNull = withGv ? &gv : nullptr;
      const std::string what = "order " + std::to_string(order) +
                               (integrals ? ", integral" : ", centre") + (withGv ? ", GV" : "");
      for (const CpuKernelLevel level : cpuKernelLevelsThisCpuRuns()) {
        const Propagated cpu = cpuPropagate<float>(current, accumulated, res, order, integrals,
                                                   steps, gvOrNull, level);
        EXPECT_LT(maxRelativeDifference(cpu.current, glCurrent), 2e-5)
            << what << ", " << cpuKernelLevelName(level);
        EXPECT_LT(maxRelativeDifference(cpu.accumulated, glAccumulated), 2e-5)
            << what << ", " << cpuKernelLevelName(level);
      }
      const Propagated cpu = cpuPropagate<double>(current, accumulated, res, order, integrals,
                                                  steps, gvOrNull, widestCpuKernelLevel());
      EXPECT_LT(maxRelativeDifference(cpu.current, glCurrent), 2e-5) << what << ", double";
      EXPECT_LT(maxRelativeDifference(cpu.accumulated, glAccumulated), 2e-5) << what << ", double";
      if (withGv) {  // the GV made a difference, so the comparison covered it
        const Propagated open = cpuPropagate<double>(current, accumulated, res, order, integrals,
                                                     steps, nullptr, widestCpuKernelLevel());
        EXPECT_GT(maxRelativeDifference(open.current, glCurrent), 1e-3) << what;
      }
    }
}

TEST(TetrahedralCpu, MatchesTheGlslKernelsOnEveryInstructionSetAndInDouble) { matchesGlsl(false); }
TEST(TetrahedralCpu, MatchesTheGlslKernelsThroughAGeometryVolume) { matchesGlsl(true); }

TEST(TetrahedralCpu, TheStrategyFindsItsGvFacesAgainWhenTheGvChanges) {
  const glm::ivec3 res(6, 6, 6);
  std::mt19937 random(5);
  test::PropagationRig gl("tetrahedral", res, test::iterationsTable(6), 1, true);
  test::PropagationRig cpu("tetrahedral", res, test::iterationsTable(6), 1, true,
                           ComputeBackend::Cpu);
  const Grid injected = test::randomFloats(gl.floatsPerGrid(), random);
  const Grid gvs[2] = {test::randomBlocking(shared::cellCount(res + 1), random),
                       test::randomBlocking(shared::cellCount(res + 1), random)};
  test::expectCpuFollowsGlAcrossFrames(
      gl, cpu,
      [&](test::PropagationRig& rig, int frame) {
        rig.load(injected);
        rig.loadGv(gvs[frame], 1);
      },
      1e-3, "GV");
}

TEST(TetrahedralCpu, ResultsDoNotDependOnTheThreadCount) {
  const glm::ivec3 res(12, 10, 9);
  std::mt19937 random(3);
  const Grid injected = test::randomFloats(std::size_t(12 * 10 * 9) * 27, random);
  const Grid gv = test::randomBlocking(shared::cellCount(res + 1), random);
  const Propagated one =
      cpuPropagate<float>(injected, injected, res, 2, true, 6, &gv, widestCpuKernelLevel(), 1);
  const Propagated two =
      cpuPropagate<float>(injected, injected, res, 2, true, 6, &gv, widestCpuKernelLevel(), 2);
  EXPECT_EQ(one.accumulated, two.accumulated);
  EXPECT_EQ(one.current, two.current);
}

}  // namespace
}  // namespace lpvlab
