// Throughput of the CPU's per-pixel kernels (Google Benchmark, in bench_cpu_kernels; prints
// figures, asserts nothing), on a 512^2 G-buffer as the default Cornell frame has:
//   direct_light_cpu: direct light (direct_lighting_cpu.h) from one point light whose shadow
//     maps (1024^2 per cube face) see every pixel lit: per pixel the light's falloff and cosine,
//     its view's projection and the 3x3 shadow taps (16 depth comparisons).
//   trilinear_cpu: trilinear rendering (trilinear_cpu.h) of a 32^3 grid of random SH
//     coefficients (order 1 and 2), without and with leak damping, on a hemisphere filling the
//     grid.
//   rsm_injection_cpu: RSM injection (rsm_vpl_cpu.h) of five 256^2 RSM views, as the Cornell
//     box's point light has, every texel a VPL on a wall of a box filling a 32^3 grid, order 1.
// Each at every instruction-set level this CPU runs (cpu_dispatch.h), the widest being what the
// pipeline runs. Reported: the median of 5 repetitions of pixels/s (all cores).

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <benchmark/benchmark.h>

#include "benchmark_support.h"

#include "framework/pipeline/direct_lighting_cpu.h"
#include "variants/injection/rsm_vpl_cpu.h"
#include "variants/rendering/trilinear_cpu.h"

namespace lpvlab {
namespace {

constexpr int kImageSize = 512;

HostImage filledImage(int size, glm::vec4 value) {
  return HostImage{size, size, 1, std::vector<glm::vec4>(std::size_t(size) * size, value)};
}

void directLight(benchmark::State& state, CpuKernelLevel level) {
  // The floor of a 1 m box, lit by a point light near its ceiling.
  HostImage position = filledImage(kImageSize, glm::vec4(0.0f));
  for (int y = 0; y < kImageSize; ++y)
    for (int x = 0; x < kImageSize; ++x)
      position.texels[std::size_t(y) * kImageSize + x] =
          glm::vec4((x + 0.5f) / kImageSize, 0.0f, (y + 0.5f) / kImageSize, 1.0f);
  const HostImage normal = filledImage(kImageSize, glm::vec4(0, 1, 0, 0));
  const HostImage albedo = filledImage(kImageSize, glm::vec4(0.5f));
  const HostImage emission = filledImage(kImageSize, glm::vec4(0.0f));
  Light light;
  light.position = glm::vec3(0.5f, 0.9f, 0.5f);
  Bounds bounds;
  bounds.extend(glm::vec3(0.0f));
  bounds.extend(glm::vec3(1.0f));
  const LightViews records = buildLightViews({light}, bounds);
  constexpr int kShadowSize = 1024;
  HostDepthImage shadow{kShadowSize, kShadowSize, int(records.views.size()),
                        std::vector<float>(std::size_t(kShadowSize) * kShadowSize * records.views.size(), 1.0f)};
  HostImage out = filledImage(kImageSize, glm::vec4(0.0f));
  const DirectCpuInputs in{.position = &position, .normal = &normal, .albedo = &albedo,
                           .emission = &emission, .shadowDepth = &shadow, .records = &records,
                           .normalOffsetTexels = 1.5f, .depthBias = 2e-5f, .instructions = level};
  directLightingCpu(in, out);  // warm-up
  for (auto _ : state) {
    directLightingCpu(in, out);
    benchmark::ClobberMemory();
  }
  state.counters["pixel/s"] = benchmark::Counter(
      double(position.texels.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
}

// Args: SH order, leak damping (0: off, the default; 1).
void trilinear(benchmark::State& state, CpuKernelLevel instructions) {
  const int order = int(state.range(0)), coefficients = (order + 1) * (order + 1);
  const float leakDamping = float(state.range(1));
  TrilinearCpuLevel level;
  level.geometry.resolution = glm::ivec3(32);
  level.geometry.cellSize = 1.0f / 32.0f;
  std::mt19937 random(1);
  std::uniform_real_distribution<float> signedUnit(-1.0f, 1.0f);
  std::vector<float> grid(std::size_t(32 * 32 * 32) * 3 * coefficients);
  for (float& v : grid) v = signedUnit(random);
  level.accumulated = grid.data();
  // A hemisphere seen from above, filling the grid: neighbouring pixels read neighbouring cells,
  // as a camera's pixels do, and the normals take every upward direction.
  HostImage position = filledImage(kImageSize, glm::vec4(0.0f));
  HostImage normal = filledImage(kImageSize, glm::vec4(0.0f));
  for (int y = 0; y < kImageSize; ++y)
    for (int x = 0; x < kImageSize; ++x) {
      const float u = 2.0f * (x + 0.5f) / kImageSize - 1.0f, v = 2.0f * (y + 0.5f) / kImageSize - 1.0f;
      const glm::vec3 n(u, std::sqrt(std::max(0.0f, 1.0f - u * u - v * v)), v);
      const std::size_t i = std::size_t(y) * kImageSize + x;
      position.texels[i] = glm::vec4(glm::vec3(0.5f, 0.05f, 0.5f) + 0.45f * n, 1.0f);
      normal.texels[i] = glm::vec4(glm::normalize(n + glm::vec3(0.0f, 1e-3f, 0.0f)), 0.0f);
    }
  const HostImage albedo = filledImage(kImageSize, glm::vec4(0.5f));
  HostImage indirect = filledImage(kImageSize, glm::vec4(0.0f));
  const TrilinearCpuSettings settings{.coefficients = coefficients, .normalOffsetCells = 0.5f,
                                      .leakDamping = leakDamping, .instructions = instructions};
  const std::span<const TrilinearCpuLevel> levels(&level, 1);
  trilinearDiffuseCpu(position, normal, albedo, levels, settings, indirect);  // warm-up
  for (auto _ : state) {
    trilinearDiffuseCpu(position, normal, albedo, levels, settings, indirect);
    benchmark::ClobberMemory();
  }
  state.counters["pixel/s"] = benchmark::Counter(
      double(position.texels.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
}

void rsmInjection(benchmark::State& state, CpuKernelLevel level) {
  constexpr int kRsmSize = 256, kViews = 5;
  const std::size_t texels = std::size_t(kRsmSize) * kRsmSize * kViews;
  HostImage position{kRsmSize, kRsmSize, kViews, std::vector<glm::vec4>(texels)};
  HostImage normal = position, flux = position;
  std::mt19937 random(1);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // View v sees wall v of a unit box (facing inwards), texel (x, y) at (x, y) / 256 across it,
  // as a cube face of a light in the box would.
  for (int view = 0; view < kViews; ++view)
    for (int y = 0; y < kRsmSize; ++y)
      for (int x = 0; x < kRsmSize; ++x) {
        const std::size_t t = (std::size_t(view) * kRsmSize + y) * kRsmSize + x;
        const int axis = view / 2;
        glm::vec3 p((x + 0.5f) / kRsmSize, (y + 0.5f) / kRsmSize, (x + 0.5f) / kRsmSize), n(0.0f);
        p[(axis + 1) % 3] = (x + 0.5f) / kRsmSize;
        p[(axis + 2) % 3] = (y + 0.5f) / kRsmSize;
        p[axis] = view % 2 == 0 ? 0.0f : 1.0f;
        n[axis] = view % 2 == 0 ? 1.0f : -1.0f;
        position.texels[t] = glm::vec4(p, 1.0f);
        normal.texels[t] = glm::vec4(n, 0.0f);
        flux.texels[t] = glm::vec4(1e-5f * unit(random), 1e-5f, 1e-5f, 1.0f);
      }
  GridGeometry grid;
  grid.resolution = glm::ivec3(32);
  grid.cellSize = 1.0f / 32.0f;
  std::vector<float> coefficients(std::size_t(32 * 32 * 32) * 3 * 4, 0.0f);
  const RsmImages rsm{&position, &normal, &flux};
  injectRsmVplsCpu(rsm, grid, 4, 1.0f, coefficients.data(), nullptr, level);  // warm-up
  for (auto _ : state) {
    injectRsmVplsCpu(rsm, grid, 4, 1.0f, coefficients.data(), nullptr, level);
    benchmark::ClobberMemory();
  }
  state.counters["pixel/s"] =
      benchmark::Counter(double(texels) * double(state.iterations()), benchmark::Counter::kIsRate);
}

const bool registered = [] {
  for (const CpuKernelLevel level : cpuKernelLevelsThisCpuRuns()) {
    const std::string isa = cpuKernelLevelName(level);
    medianOf5(benchmark::RegisterBenchmark(("rsm_injection_cpu/" + isa).c_str(), rsmInjection, level));
    medianOf5(benchmark::RegisterBenchmark(("direct_light_cpu/" + isa).c_str(), directLight, level));
    medianOf5(benchmark::RegisterBenchmark(("trilinear_cpu/" + isa).c_str(), trilinear, level)
                  ->ArgsProduct({{1, 2}, {0, 1}})
                  ->ArgNames({"order", "leak_damping"}));
  }
  return true;
}();

}  // namespace
}  // namespace lpvlab
