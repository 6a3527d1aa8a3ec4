// Throughput of the CPU kernels (Google Benchmark; prints figures, asserts nothing):
//   build/tests/bench_cpu_kernels [--benchmark_filter=...]
// Standard gathering at SH orders 1-3, grids 32^3 and 64^3, on every CPU instruction set this
// machine has, all cores, iterations paired as the strategy runs them (the accumulated grid
// updated every other iteration, StepAccumulation). Reported per configuration: the median of 5
// repetitions (after one untimed warm-up iteration) of cell-iterations/s and of multiply-adds/s,
// counting the kernel's own arithmetic (standardGatherMultiplyAdds per channel: the skipped zeros
// not counted). Standard propagation at order 1 by gathering and scattering, without a GV, with a
// GV and with its bounces (standard_variants/auto: a GV of four walls, as a box's, the kind of
// scene LPV blocks in), and the per-frame cost of finding what that GV does to every face
// (standard_occlusion_setup: makeStandardOcclusion, once per frame).
// And the machine's multiply-add peak per instruction set (fma_peak/...), all cores running
// independent chains of vector multiply-adds, so a kernel's figure can be read as a fraction of
// it (SSE2 has no fused multiply-add: there a multiply and an add count as one).

#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>

#include <cstring>
#include <random>
#include <thread>
#include <type_traits>

#include "benchmark_support.h"
#include "framework/math/dual.h"
#include "framework/math/solid_angle.h"
#include "variants/propagation/standard_cpu.h"

namespace lpvlab {
namespace {

// The propagation's face table for Real: on dual numbers with the two solid angles as the
// parameters in slots 0 and 1 (what a fit differentiates).
template <class Real>
StandardFaceTable<Real> benchmarkTable(int order) {
  const double far = cubeFaceSolidAngles().farFace, side = cubeFaceSolidAngles().sideFace;
  if constexpr (std::is_same_v<Real, Dual>)
    return makeStandardFaceTable<Dual, Dual>(order, Dual::parameter(far, 0),
                                             Dual::parameter(side, 1));
  else
    return makeStandardFaceTable<Real>(order, far, side);
}

template <class Real>
void standardGather(benchmark::State& state, const std::string& isa) {
  const int resolution = int(state.range(0)), order = int(state.range(1));
  const glm::ivec3 res(resolution);
  const StandardFaceTable<Real> table = benchmarkTable<Real>(order);
  const std::size_t cells = std::size_t(resolution) * resolution * resolution;
  const std::size_t floats = cells * 3 * table.coefficients;
  std::vector<Real> current(floats), next(floats), accumulated(floats, Real(0.0));
  std::mt19937 random(1);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  for (Real& v : current) v = Real(value(random));
  standardGatherCpu(table, res, current.data(), next.data(), accumulated.data(), isa);  // warm-up
  // Iterations paired as the strategy runs them (StepAccumulation).
  int iteration = 0;
  for (auto _ : state) {
    standardGatherCpu(table, res, current.data(), next.data(), accumulated.data(), isa, 0,
                      static_cast<const StandardOcclusion<Real>*>(nullptr),
                      pairedAccumulation(iteration++, 1 << 30));
    std::swap(current, next);
    benchmark::ClobberMemory();
  }
  const double cellIterations = double(cells) * double(state.iterations());
  state.counters["cell_it/s"] = benchmark::Counter(cellIterations, benchmark::Counter::kIsRate);
  state.counters["madd/s"] = benchmark::Counter(
      cellIterations * 3 * standardGatherMultiplyAdds(table.coefficients), benchmark::Counter::kIsRate);
}

// A GV (res + 1 cells per axis) whose cells on four walls (x = 1, y = 1, z = 1 and x = res / 2)
// block like a surface facing +x, +y, +z or -x, with albedo 0.5.
struct WallsGv {
  std::vector<float> blocking, albedo;
};
WallsGv wallsGv(int resolution) {
  const int n = resolution + 1, cells = n * n * n;
  WallsGv gv{std::vector<float>(std::size_t(4) * cells, 0.0f), std::vector<float>(std::size_t(4) * cells, 0.0f)};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const int axis = x == 1 ? 3 : y == 1 ? 1 : z == 1 ? 2 : x == resolution / 2 ? 3 : -1;
        if (axis < 0) continue;
        const int i = x + n * (y + n * z);
        gv.blocking[i] = 0.8f;                                                  // c0
        gv.blocking[std::size_t(axis) * cells + i] = axis == 2 ? 0.8f : -0.8f;  // band 1
        for (int c = 0; c < 3; ++c) gv.albedo[std::size_t(4) * i + c] = 0.5f;
        gv.albedo[std::size_t(4) * i + 3] = 1.0f;
      }
  return gv;
}

// Args: resolution, scatter (0, 1), occlusion (0 none, 1 GV, 2 GV and bounces).
void standardVariants(benchmark::State& state) {
  const int resolution = int(state.range(0));
  const bool scatter = state.range(1) != 0;
  const int occlusion = int(state.range(2));
  const glm::ivec3 res(resolution);
  const auto table = makeStandardFaceTable<float>(1, cubeFaceSolidAngles().farFace,
                                                  cubeFaceSolidAngles().sideFace);
  const WallsGv gv = wallsGv(resolution);
  const StandardOcclusion<float> faces = makeStandardOcclusion(
      table, res, gv.blocking.data(), occlusion == 2 ? gv.albedo.data() : nullptr);
  const std::size_t cells = std::size_t(resolution) * resolution * resolution;
  std::vector<float> current(cells * 12), next(cells * 12), accumulated(cells * 12, 0.0f);
  std::mt19937 random(1);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  for (float& v : current) v = value(random);
  const StandardOcclusion<float>* used = occlusion > 0 ? &faces : nullptr;
  standardIterationCpu(scatter, table, res, current.data(), next.data(), accumulated.data(), "auto",
                       0, used,
                       StepAccumulation::Target);  // warm-up
  int iteration = 0;
  for (auto _ : state) {
    standardIterationCpu(scatter, table, res, current.data(), next.data(), accumulated.data(),
                         "auto", 0, used, pairedAccumulation(iteration++, 1 << 30));
    std::swap(current, next);
    benchmark::ClobberMemory();
  }
  state.counters["cell_it/s"] =
      benchmark::Counter(double(cells) * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["bounce_faces"] = double(faces.bounces.size());
}

// Args: resolution, bounces (0, 1).
void standardOcclusionSetup(benchmark::State& state) {
  const int resolution = int(state.range(0));
  const auto table = makeStandardFaceTable<float>(1, cubeFaceSolidAngles().farFace,
                                                  cubeFaceSolidAngles().sideFace);
  const WallsGv gv = wallsGv(resolution);
  for (auto _ : state)
    benchmark::DoNotOptimize(makeStandardOcclusion(table, glm::ivec3(resolution), gv.blocking.data(),
                                                   state.range(1) ? gv.albedo.data() : nullptr));
}

// `rounds` of kChains independent multiply-add chains on registers of `Bytes`: enough chains to
// hide the latency of each, so the loop runs at the units' throughput. Returns the lanes' sum so
// the work is not optimised away.
constexpr int kChains = 12;
template <int Bytes>
[[gnu::always_inline]] inline float multiplyAddChains(long rounds) {
  typedef float V __attribute__((vector_size(Bytes)));
  V chain[kChains];
  for (int c = 0; c < kChains; ++c) chain[c] = V{} + float(c);
  const V scale = V{} + 0.999f, offset = V{} + 1e-3f;
  for (long r = 0; r < rounds; ++r)
#pragma GCC unroll 12
    for (int c = 0; c < kChains; ++c) chain[c] = chain[c] * scale + offset;
  float lanes[kChains * Bytes / 4];
  std::memcpy(lanes, chain, sizeof chain);
  float sum = 0.0f;
  for (float lane : lanes) sum += lane;
  return sum;
}
float chainsX86_64(long rounds) { return multiplyAddChains<16>(rounds); }
__attribute__((target("arch=x86-64-v3"))) float chainsV3(long rounds) {
  return multiplyAddChains<32>(rounds);
}
__attribute__((target("arch=x86-64-v4"))) float chainsV4(long rounds) {
  return multiplyAddChains<64>(rounds);
}

void multiplyAddPeak(benchmark::State& state, const std::string& isa) {
  const auto chains = isa == "x86-64-v4" ? chainsV4 : isa == "x86-64-v3" ? chainsV3 : chainsX86_64;
  const int lanes = isa == "x86-64-v4" ? 16 : isa == "x86-64-v3" ? 8 : 4;
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  constexpr long kRounds = 1 << 22;
  float sink = 0.0f;
  for (auto _ : state) {
    tbb::parallel_for(0, cores, [&](int) { benchmark::DoNotOptimize(chains(kRounds)); });
    benchmark::DoNotOptimize(sink);
  }
  state.counters["madd/s"] = benchmark::Counter(
      double(state.iterations()) * cores * kRounds * kChains * lanes, benchmark::Counter::kIsRate);
}

const bool registered = [] {
  for (const std::string& isa : supportedCpuKernelInstructionSets())
    medianOf5(
        benchmark::RegisterBenchmark(("standard_gather/" + isa).c_str(), standardGather<float>, isa)
            ->ArgsProduct({{32, 64}, {1, 2, 3}})
            ->ArgNames({"res", "order"}));
  // On dual numbers (a fit's derivative frames): a register holds Bytes / 8 cells, each a value and
  // four derivatives, so the width of the instruction set is the width of the derivatives' SIMD.
  for (const std::string& isa : supportedCpuKernelInstructionSets())
    medianOf5(benchmark::RegisterBenchmark(("standard_gather_dual/" + isa).c_str(),
                                           standardGather<Dual>, isa)
                  ->ArgsProduct({{32}, {1, 2}})
                  ->ArgNames({"res", "order"}));
  medianOf5(benchmark::RegisterBenchmark("standard_variants/auto", standardVariants)
      ->ArgsProduct({{32, 64}, {0, 1}, {0, 1, 2}})
      ->ArgNames({"res", "scatter", "gv"}));
  medianOf5(benchmark::RegisterBenchmark("standard_occlusion_setup", standardOcclusionSetup)
      ->ArgsProduct({{32, 64}, {0, 1}})
      ->ArgNames({"res", "bounces"}));
  for (const std::string& isa : supportedCpuKernelInstructionSets())
    medianOf5(benchmark::RegisterBenchmark(("fma_peak/" + isa).c_str(), multiplyAddPeak, isa));
  return true;
}();

}  // namespace
}  // namespace lpvlab

BENCHMARK_MAIN();
