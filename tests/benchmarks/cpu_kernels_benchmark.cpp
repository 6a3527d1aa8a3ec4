// Throughput of the CPU kernels (Google Benchmark; prints figures, asserts nothing):
//   build/tests/bench_cpu_kernels [--benchmark_filter=...]
// Standard gathering at SH orders 1-3, grids 32^3 and 64^3, on every CPU instruction set this
// machine has, all cores. Reported per configuration: the median of 5 repetitions (after one
// untimed warm-up iteration) of cell-iterations/s and of multiply-adds/s, counting the kernel's
// arithmetic: per cell-iteration and channel, 6 neighbours x 5 faces x N multiply-adds for the
// intensities towards the faces and 6 normals x N for the lobes, so 3 x 36N
// (N = (order + 1)^2), the tables' zeros included.

#include <random>

#include <benchmark/benchmark.h>

#include "framework/math/solid_angle.h"
#include "variants/propagation/standard_cpu.h"

namespace lpvlab {
namespace {

void standardGather(benchmark::State& state, const std::string& isa) {
  const int resolution = int(state.range(0)), order = int(state.range(1));
  const glm::ivec3 res(resolution);
  const auto table = makeStandardFaceTable<float>(order, cubeFaceSolidAngles().farFace,
                                                  cubeFaceSolidAngles().sideFace);
  const std::size_t cells = std::size_t(resolution) * resolution * resolution;
  const std::size_t floats = cells * 3 * table.coefficients;
  std::vector<float> current(floats), next(floats), accumulated(floats, 0.0f);
  std::mt19937 random(1);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  for (float& v : current) v = value(random);
  standardGatherCpu(table, res, current.data(), next.data(), accumulated.data(), isa);  // warm-up
  for (auto _ : state) {
    standardGatherCpu(table, res, current.data(), next.data(), accumulated.data(), isa);
    std::swap(current, next);
    benchmark::ClobberMemory();
  }
  const double cellIterations = double(cells) * double(state.iterations());
  state.counters["cell_it/s"] = benchmark::Counter(cellIterations, benchmark::Counter::kIsRate);
  state.counters["madd/s"] = benchmark::Counter(cellIterations * 3 * 36 * table.coefficients,
                                                benchmark::Counter::kIsRate);
}

const bool registered = [] {
  for (const std::string& isa : supportedCpuKernelInstructionSets())
    benchmark::RegisterBenchmark(("standard_gather/" + isa).c_str(), standardGather, isa)
        ->ArgsProduct({{32, 64}, {1, 2, 3}})
        ->ArgNames({"res", "order"})
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond)
        ->Repetitions(5)
        ->ReportAggregatesOnly(true);
  return true;
}();

}  // namespace
}  // namespace lpvlab

BENCHMARK_MAIN();
