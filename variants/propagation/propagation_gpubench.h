#pragma once
// The inputs lpvlab-gpubench's propagation cases share (gpu_bench_inputs.h's hashed values): a
// light grid and its accumulated grid with coefficients in [-1, 1] (so the kernels' clamps act),
// and the geometry volume: a blocking potential with c0 in [0, 1.5] and band 1 in [-1, 1] (as the
// tests' randomGv: transmittances over all of [0, 1]) and its albedo (rho A, A) with A in
// [0.1, 1] and rho in [0, 1] per channel.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/dual_buffer.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "framework/gpubench/gpu_bench_inputs.h"

namespace lpvlab {

inline std::size_t benchCells(const glm::ivec3& r) { return std::size_t(r.x) * r.y * r.z; }

// "current" and "accumulated": 3 x coefficients floats per cell of `resolution`.
inline GpuBenchInputs benchLightGrids(const glm::ivec3& resolution, int coefficients) {
  const std::size_t floats = 3 * std::size_t(coefficients) * benchCells(resolution);
  return {{"current", benchValues(floats, 1, -1.0f, 1.0f)},
          {"accumulated", benchValues(floats, 2, -1.0f, 1.0f)}};
}

// The GV of a light grid of `resolution` (one more cell per axis), coefficient-major.
inline std::vector<float> benchGvBlocking(const glm::ivec3& resolution) {
  const std::size_t cells = benchCells(resolution + 1);
  std::vector<float> gv = benchValues(4 * cells, 3, -1.0f, 1.0f);
  for (std::size_t i = 0; i < cells; ++i) gv[i] = 0.75f * (gv[i] + 1.0f);  // c0 >= 0
  return gv;
}

inline std::vector<float> benchGvAlbedo(const glm::ivec3& resolution) {
  const std::size_t cells = benchCells(resolution + 1);
  const std::vector<float> area = benchValues(cells, 4, 0.1f, 1.0f);
  const std::vector<float> rho = benchValues(3 * cells, 5, 0.0f, 1.0f);
  std::vector<float> out(4 * cells);
  for (std::size_t i = 0; i < cells; ++i) {
    for (int c = 0; c < 3; ++c) out[4 * i + c] = area[i] * rho[3 * i + c];
    out[4 * i + 3] = area[i];
  }
  return out;
}

// What a propagation case's checksum covers: the accumulated grid and the last step's light.
inline double benchGridChecksum(const DualBuffer& accumulated, const DualBuffer& current) {
  std::vector<float> values(current.size() / sizeof(float));
  accumulated.download(values.data(), current.size());
  const double sum = benchChecksum(values);
  current.download(values.data(), current.size());
  return sum + benchChecksum(values);
}

// The named input, which the case put there itself.
inline const std::vector<float>& benchInput(const GpuBenchInputs& inputs, const char* name) {
  for (const auto& [n, values] : inputs)
    if (n == name) return values;
  return inputs.front().second;  // not reached: every case names what it uploads
}

}  // namespace lpvlab
