// The CPU kernels of directed and tetrahedral propagation (part of bench_cpu_kernels):
//   directed_gather/auto: one gather step at 32^3 and 64^3, SH orders 1-2, every cell
//     reprojecting (a random normal in each: the finishing's worst case), without and with a GV;
//   directed_cells_setup: makeDirectedCells for 32 iterations from a normal grid with a third of
//     its cells injected (the dilation and every reached cell's gain), once per frame when the
//     injected normals change;
//   tetrahedral_step/<isa>: one lattice step at 32^3 (12 lattice cells per cube), SH orders 1-3,
//     with and without a GV, on every CPU instruction set this machine has; cube-steps/s (the
//     cubic cells, as the variant benchmark counts) and multiply-adds/s
//     (tetrahedralStepMultiplyAdds per lattice cell and channel);
//   tetrahedral_occlusion_setup: what a GV does to every lattice face, once per GV.
// Medians of 5 repetitions after an untimed warm-up (benchmark_support.h).

#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "benchmark_support.h"
#include "framework/core/cpu_features.h"
#include "framework/math/solid_angle.h"
#include "variants/propagation/directed_cpu.h"
#include "variants/propagation/tetrahedral_cpu.h"

namespace lpvlab {
namespace {

std::vector<float> randomValues(std::size_t count, std::mt19937& random, float low, float high) {
  std::uniform_real_distribution<float> value(low, high);
  std::vector<float> v(count);
  for (float& x : v) x = value(random);
  return v;
}

// A GV of random blocking (c0 in [0, 0.6], band 1 smaller), res + 1 cells per axis.
std::vector<float> randomGv(int resolution, std::mt19937& random) {
  const std::size_t cells = std::size_t(resolution + 1) * (resolution + 1) * (resolution + 1);
  std::vector<float> gv = randomValues(4 * cells, random, -0.4f, 0.4f);
  for (std::size_t i = 0; i < cells; ++i) gv[i] = 0.3f + 0.75f * gv[i];
  return gv;
}

// Args: resolution, order, gv (0, 1).
void directedGather(benchmark::State& state) {
  const int resolution = int(state.range(0)), order = int(state.range(1));
  const glm::ivec3 res(resolution);
  const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  const auto table = makeStandardFaceTable<float>(order, angles.farFace, angles.sideFace);
  const std::size_t cells = std::size_t(resolution) * resolution * resolution;
  std::mt19937 random(1);
  std::vector<float> normals = randomValues(4 * cells, random, -1.0f, 1.0f);
  const ReprojectedCells<float> reprojected =
      makeDirectedCells(table, res, normals, 1, false, angles.farFace, angles.sideFace);
  StandardOcclusion<float> occlusion;
  if (state.range(2))
    occlusion = makeStandardOcclusion(table, res, randomGv(resolution, random).data(), nullptr);
  const std::size_t floats = cells * 3 * table.coefficients;
  std::vector<float> current = randomValues(floats, random, -1.0f, 1.0f), next(floats),
                     accumulated(floats);
  const StandardOcclusion<float>* used = state.range(2) ? &occlusion : nullptr;
  standardGatherCpu(table, res, current.data(), next.data(), accumulated.data(), "auto", 0, used,
                    StepAccumulation::Target, &reprojected, 0);  // warm-up
  int iteration = 0;
  for (auto _ : state) {
    standardGatherCpu(table, res, current.data(), next.data(), accumulated.data(), "auto", 0, used,
                      pairedAccumulation(iteration++, 1 << 30), &reprojected, 0);
    std::swap(current, next);
    benchmark::ClobberMemory();
  }
  state.counters["cell_it/s"] =
      benchmark::Counter(double(cells) * double(state.iterations()), benchmark::Counter::kIsRate);
}

void directedCellsSetup(benchmark::State& state) {
  const int resolution = int(state.range(0));
  const glm::ivec3 res(resolution);
  const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  const auto table = makeStandardFaceTable<float>(1, angles.farFace, angles.sideFace);
  std::mt19937 random(2);
  std::vector<float> normals =
      randomValues(4 * std::size_t(resolution) * resolution * resolution, random, -1.0f, 1.0f);
  for (std::size_t i = 0; i < normals.size(); i += 4)
    if (i % 12 != 0) normals[i] = normals[i + 1] = normals[i + 2] = normals[i + 3] = 0.0f;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        makeDirectedCells(table, res, normals, 32, true, angles.farFace, angles.sideFace));
}

// Args: resolution, order, gv (0, 1).
void tetrahedralStep(benchmark::State& state, CpuKernelLevel level) {
  const int resolution = int(state.range(0)), order = int(state.range(1));
  const glm::ivec3 res(resolution);
  const auto table = makeTetrahedralTable<float>(order, true);
  TetrahedralLattice<float> lattice(res, table.coefficients);
  std::mt19937 random(3);
  const std::size_t cubes = std::size_t(resolution) * resolution * resolution;
  const std::vector<float> grid = randomValues(cubes * 3 * table.coefficients, random, -1.0f, 1.0f);
  tetrahedralSplitCpu(grid.data(), lattice);
  TetrahedralOcclusion<float> occlusion;
  if (state.range(2))
    occlusion = makeTetrahedralOcclusion(lattice, randomGv(resolution, random).data());
  const TetrahedralOcclusion<float>* used = state.range(2) ? &occlusion : nullptr;
  tetrahedralStepCpu(table, lattice, used, level);  // warm-up
  for (auto _ : state) {
    tetrahedralStepCpu(table, lattice, used, level);
    benchmark::ClobberMemory();
  }
  const double steps = double(cubes) * double(state.iterations());
  state.counters["cube_it/s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
  state.counters["madd/s"] =
      benchmark::Counter(steps * 12 * 3 * tetrahedralStepMultiplyAdds(table.coefficients),
                         benchmark::Counter::kIsRate);
}

void tetrahedralOcclusionSetup(benchmark::State& state) {
  const int resolution = int(state.range(0));
  TetrahedralLattice<float> lattice(glm::ivec3(resolution), 4);
  std::mt19937 random(4);
  const std::vector<float> gv = randomGv(resolution, random);
  for (auto _ : state) benchmark::DoNotOptimize(makeTetrahedralOcclusion(lattice, gv.data()));
}

const bool registered = [] {
  medianOf5(benchmark::RegisterBenchmark("directed_gather/auto", directedGather)
                ->ArgsProduct({{32, 64}, {1, 2}, {0, 1}})
                ->ArgNames({"res", "order", "gv"}));
  medianOf5(benchmark::RegisterBenchmark("directed_cells_setup", directedCellsSetup)
                ->Arg(32)
                ->ArgName("res"));
  for (const CpuKernelLevel level : cpuKernelLevelsThisCpuRuns())
    medianOf5(benchmark::RegisterBenchmark(
                  (std::string("tetrahedral_step/") + cpuKernelLevelName(level)).c_str(),
                  tetrahedralStep, level)
                  ->ArgsProduct({{32}, {1, 2, 3}, {0, 1}})
                  ->ArgNames({"res", "order", "gv"}));
  medianOf5(benchmark::RegisterBenchmark("tetrahedral_occlusion_setup", tetrahedralOcclusionSetup)
                ->Arg(32)
                ->ArgName("res"));
  return true;
}();

}  // namespace
}  // namespace lpvlab
