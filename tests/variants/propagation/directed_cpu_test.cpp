// Directed propagation's CPU kernel (variants/propagation/directed_cpu.h: the standard CPU kernel
// finishing the cells with a normal by their second reprojection):
//   a. the iteration from which each cell reprojects is the first at which the dilation model
//      (directed_model.h, step by step over the whole grid) gives it a normal, with a sparse
//      random grid holding exactly opposite normals (whose mean cancels) and with dilation off;
//   b. float on every CPU instruction set this machine has, and double, against the GLSL
//      kernels (dilation and gather) over three iterations of random light, with and without a
//      random geometry volume (occluding from the second iteration), SH orders 1-3;
//   c. the strategy on the CPU backend finds its cells again when the injected normals change
//      from one frame to the next (and gives GL's grids for both);
//   d. results do not depend on the thread count; a normal grid of the wrong size is an Error.
// The tests of both backends' kernels against the C++ model, flux and the floor are in
// directed_test.cpp.

#include "variants/propagation/directed_cpu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "cpu_comparison.h"
#include "directed_model.h"
#include "error_support.h"
#include "framework/math/solid_angle.h"
#include "variants/resources/geometry_volume.h"
#include "propagation_rig.h"

namespace lpvlab {
namespace {

using test::Grid;
using test::maxRelativeDifference;
using test::Propagated;

const double kFar = cubeFaceSolidAngles().farFace;
const double kSide = cubeFaceSolidAngles().sideFace;

// A sparse random normal grid (about a third of the cells), with a pair of exactly opposite
// normals two cells apart so that the cell between them has a mean of zero.
std::vector<float> sparseNormals(const glm::ivec3& res, std::mt19937& random) {
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  std::vector<float> normals(std::size_t(4) * test::cells(res), 0.0f);
  for (std::size_t i = 0; i < normals.size(); i += 4)
    if (uniform(random) > 0.35f) {
      for (int k = 0; k < 3; ++k) normals[i + k] = uniform(random);
      normals[i + 3] = 1.0f;
    }
  const auto set = [&](const glm::ivec3& cell, float y) {
    const std::size_t i = std::size_t(4) * shared::cellIndex(cell, res);
    normals[i] = normals[i + 2] = 0.0f;
    normals[i + 1] = y;
    normals[i + 3] = 1.0f;
  };
  set({0, 0, 0}, 1.0f);
  set({2, 0, 0}, -1.0f);
  const std::size_t between = std::size_t(4) * shared::cellIndex({1, 0, 0}, res);
  for (int k = 0; k < 4; ++k) normals[between + k] = 0.0f;
  return normals;
}

TEST(DirectedCpu, CellsReprojectFromTheIterationTheDilationGivesThemANormal) {
  const glm::ivec3 res(9, 7, 8);
  std::mt19937 random(3);
  // Sparser than sparseNormals: a few VPL cells, so that dilation takes several steps.
  std::vector<float> normals(std::size_t(4) * test::cells(res), 0.0f);
  for (const glm::ivec3 cell : {glm::ivec3(1, 1, 1), glm::ivec3(7, 5, 6), glm::ivec3(3, 3, 3)}) {
    const std::size_t i = std::size_t(4) * shared::cellIndex(cell, res);
    normals[i] = 0.3f;
    normals[i + 1] = cell.x == 3 ? -0.7f : 0.7f;
    normals[i + 3] = 1.0f;
  }
  // Two exactly opposite normals with an empty cell between them, whose mean cancels.
  normals[4 * std::size_t(shared::cellIndex({6, 0, 0}, res)) + 1] = 1.0f;
  normals[4 * std::size_t(shared::cellIndex({8, 0, 0}, res)) + 1] = -1.0f;
  const StandardFaceTable<double> table = makeStandardFaceTable<double>(1, kFar, kSide);
  const int iterations = 6;
  for (const bool dilation : {true, false}) {
    const ReprojectedCells<double> cells =
        makeDirectedCells(table, res, normals, iterations, dilation, kFar, kSide);
    // The model: the normals the gather of iteration i sees are dilate^(i + 1)(injected).
    std::vector<float> seen = normals;
    std::vector<std::vector<float>> perIteration;
    for (int i = 0; i < iterations; ++i) {
      if (dilation) seen = test::dilate(seen, res);
      perIteration.push_back(seen);
    }
    int reached = 0, never = 0;
    test::forEachCell(res, [&](const glm::ivec3& c) {
      double expected = ReprojectedCells<double>::kNever;
      for (int i = iterations - 1; i >= 0; --i)
        if (shared::directedHasNormal(test::normalOf(perIteration[i], res, c))) expected = i;
      const double got = cells.since[std::size_t(c.y + res.y * c.z) * cells.width + c.x];
      EXPECT_EQ(got, expected) << "cell " << c.x << "," << c.y << "," << c.z
                               << (dilation ? "" : " without dilation");
      (expected == ReprojectedCells<double>::kNever ? never : reached) += 1;
    });
    // Without dilation the five injected cells reproject from the start; with it, many more, and
    // some are never reached in six steps.
    EXPECT_EQ(reached, dilation ? reached : 5);
    if (dilation) {
      EXPECT_GT(reached, 100);
    }
    EXPECT_GT(never, 5) << dilation;
    if (dilation) {
      EXPECT_EQ(cells.since[std::size_t(0) * cells.width + 7], ReprojectedCells<double>::kNever)
          << "the cell between opposite normals has none at the first step";
    }
  }
}

// `iterations` CPU steps from `injected` with `normals`, the GV (if any) from iteration 1 on.
// `released`: the light in two grids (directed.cpp's default), the attached one reprojected and
// the free one standard, each cell released as makeReleasedCells says; else one grid, every
// cell reprojecting (release = false).
template <class Real>
Propagated cpuPropagate(const Grid& injected, const std::vector<float>& normals,
                        const glm::ivec3& res, int order, int iterations, const Grid* gv,
                        bool released, const std::string& isa = "auto", int threads = 0) {
  const StandardFaceTable<Real> table = makeStandardFaceTable<Real>(order, kFar, kSide);
  const ReprojectedCells<Real> cells =
      makeDirectedCells(table, res, normals, iterations, true, kFar, kSide);
  const ReleasedCells release =
      makeReleasedCells(res, normals, iterations, true, std::cos(10.0 * M_PI / 180.0));
  StandardOcclusion<Real> occlusion;
  if (gv) occlusion = makeStandardOcclusion(table, res, gv->data(), nullptr);
  std::vector<Real> current(injected.begin(), injected.end()), next(current.size()),
      accumulated = current, free(current.size(), Real(0)), freeNext(current.size());
  const std::size_t cellCount = std::size_t(res.x) * res.y * res.z;
  for (int i = 0; i < iterations; ++i) {
    const StandardOcclusion<Real>* faces = gv && i >= 1 ? &occlusion : nullptr;
    if (released) {
      for (std::size_t cell = 0; cell < cellCount; ++cell)
        if (!release.keeps(cell, i))
          for (std::size_t k = cell; k < current.size(); k += cellCount) {
            free[k] += current[k];
            current[k] = Real(0);
          }
      standardGatherCpu(table, res, free.data(), freeNext.data(), accumulated.data(), isa,
                        threads, faces, pairedAccumulation(i, iterations));
      std::swap(free, freeNext);
    }
    standardGatherCpu(table, res, current.data(), next.data(), accumulated.data(), isa, threads,
                      faces, pairedAccumulation(i, iterations), &cells, i);
    std::swap(current, next);
  }
  if (released)
    for (std::size_t k = 0; k < current.size(); ++k) current[k] += free[k];
  return {std::vector<double>(current.begin(), current.end()),
          std::vector<double>(accumulated.begin(), accumulated.end())};
}

void matchesGlsl(bool withGv, bool released) {
  const glm::ivec3 res(9, 6, 7);
  std::mt19937 random(withGv ? 31 : 13);
  const int iterations = 3;
  for (int order = 1; order <= 3; ++order) {
    toml::table table = test::iterationsTable(iterations);
    if (!released) table.insert("release", false);
    test::PropagationRig rig("directed", res, table, order, withGv);
    const Grid injected = test::randomFloats(rig.floatsPerGrid(), random);
    // Released, random normals would release every cell and leave standard propagation.
    const std::vector<float> normals =
        released ? test::regionNormals(res, random, 0.6f) : sparseNormals(res, random);
    const Grid gv = test::randomGv(res + 1, random);
    rig.load(injected);
    rig.loadNormals(normals);
    if (withGv) rig.loadGv(gv, 1);
    rig.propagate();
    const Grid glCurrent = rig.current(), glAccumulated = rig.accumulated();
    const Grid* gvOrNull = withGv ? &gv : nullptr;
    const std::string what = "order " + std::to_string(order) + (withGv ? ", GV" : "") +
                             (released ? ", released" : ", read literally");
    for (const std::string& isa : supportedCpuKernelInstructionSets()) {
      const Propagated cpu =
          cpuPropagate<float>(injected, normals, res, order, iterations, gvOrNull, released, isa);
      EXPECT_LT(maxRelativeDifference(cpu.current, glCurrent), 2e-5) << what << ", " << isa;
      EXPECT_LT(maxRelativeDifference(cpu.accumulated, glAccumulated), 2e-5) << what << ", " << isa;
    }
    const Propagated cpu =
        cpuPropagate<double>(injected, normals, res, order, iterations, gvOrNull, released);
    EXPECT_LT(maxRelativeDifference(cpu.current, glCurrent), 2e-5) << what << ", double";
    EXPECT_LT(maxRelativeDifference(cpu.accumulated, glAccumulated), 2e-5) << what << ", double";
    // The reprojection made a difference, so the comparison covered it: standard propagation
    // of the same light differs.
    test::PropagationRig standard("standard", res, test::iterationsTable(iterations), order,
                                  withGv);
    standard.load(injected);
    if (withGv) standard.loadGv(gv, 1);
    standard.propagate();
    const Grid standardCurrent = standard.current();
    EXPECT_GT(maxRelativeDifference(
                  std::vector<double>(standardCurrent.begin(), standardCurrent.end()), glCurrent),
              1e-2)
        << what;
  }
}

TEST(DirectedCpu, MatchesTheGlslKernelsOnEveryInstructionSetAndInDouble) {
  matchesGlsl(false, true);
  matchesGlsl(false, false);
}
TEST(DirectedCpu, MatchesTheGlslKernelsThroughAGeometryVolume) {
  matchesGlsl(true, true);
  matchesGlsl(true, false);
}

TEST(DirectedCpu, TheStrategyFindsItsCellsAgainWhenTheNormalsChange) {
  const glm::ivec3 res(8, 8, 8);
  std::mt19937 random(8);
  test::PropagationRig gl("directed", res, test::iterationsTable(4), 2);
  test::PropagationRig cpu("directed", res, test::iterationsTable(4), 2, false,
                           ComputeBackend::Cpu);
  const Grid injected = test::randomFloats(gl.floatsPerGrid(), random);
  const std::vector<float> normals[2] = {sparseNormals(res, random), sparseNormals(res, random)};
  test::expectCpuFollowsGlAcrossFrames(
      gl, cpu,
      [&](test::PropagationRig& rig, int frame) {
        rig.load(injected);
        rig.loadNormals(normals[frame]);
      },
      1e-2, "normals");
}

TEST(DirectedCpu, ResultsDoNotDependOnTheThreadCountAndBadNormalsAreErrors) {
  const glm::ivec3 res(16, 16, 16);
  std::mt19937 random(4);
  const Grid injected = test::randomFloats(std::size_t(16 * 16 * 16) * 27, random);
  const std::vector<float> normals = sparseNormals(res, random);
  const Grid gv = test::randomGv(res + 1, random);
  const Propagated one = cpuPropagate<float>(injected, normals, res, 2, 4, &gv, true, "auto", 1);
  const Propagated two = cpuPropagate<float>(injected, normals, res, 2, 4, &gv, true, "auto", 2);
  EXPECT_EQ(one.accumulated, two.accumulated);
  const StandardFaceTable<float> table = makeStandardFaceTable<float>(1, kFar, kSide);
  EXPECT_TRUE(test::contains(test::errorOf([&] {
                               makeDirectedCells(table, res, std::vector<float>(7, 0.0f), 4, true,
                                                 kFar, kSide);
                             }),
                             "normal grid holds 7 floats"));
}

}  // namespace
}  // namespace lpvlab
