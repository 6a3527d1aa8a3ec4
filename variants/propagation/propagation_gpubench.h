#pragma once
// The inputs lpvlab-gpubench's propagation cases share (gpu_bench_inputs.h's hashed values): a
// light grid and its accumulated grid with coefficients in [-1, 1] (so the kernels' clamps act),
// and the geometry volume: a blocking potential with c0 in [0, 1.5] and band 1 in [-1, 1] (as the
// tests' randomGv: transmittances over all of [0, 1]) and its albedo (rho A, A) with A in
// [0.1, 1] and rho in [0, 1] per channel.

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/dual_buffer.h"
#include "framework/gl/resources.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "framework/gpubench/gpu_bench_inputs.h"
#include "framework/math/shared.h"

namespace lpvlab {

// "current" and "accumulated": 3 x coefficients floats per cell of `resolution`.
inline GpuBenchInputs benchLightGrids(const glm::ivec3& resolution, int coefficients) {
  const std::size_t floats = 3 * std::size_t(coefficients) * std::size_t(shared::cellCount(resolution));
  return {{"current", benchValues(floats, 1, -1.0f, 1.0f)},
          {"accumulated", benchValues(floats, 2, -1.0f, 1.0f)}};
}

// The GV of a light grid of `resolution` (one more cell per axis), coefficient-major.
inline std::vector<float> benchGvBlocking(const glm::ivec3& resolution) {
  const std::size_t cells = std::size_t(shared::cellCount(resolution + 1));
  std::vector<float> gv = benchValues(4 * cells, 3, -1.0f, 1.0f);
  for (std::size_t i = 0; i < cells; ++i) gv[i] = 0.75f * (gv[i] + 1.0f);  // c0 >= 0
  return gv;
}

inline std::vector<float> benchGvAlbedo(const glm::ivec3& resolution) {
  const std::size_t cells = std::size_t(shared::cellCount(resolution + 1));
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
  return benchChecksumOf(accumulated) + benchChecksumOf(current);
}

// What every propagation case has: its inputs, each uploaded by reset() into the buffer
// addInput allocated for it, the light grid (current_) and the accumulated grid, and the
// checksum over both. A case adds its kernel, its other inputs and run().
class PropagationBench : public GpuBenchCase {
public:
  void reset() override {
    for (const auto& [name, upload] : uploads_) upload(benchInput(inputs_, name));
    glFinish();  // the uploads are not the kernel's time
  }
  double checksum() const override { return benchGridChecksum(accumulated_, current_); }
  const GpuBenchInputs& inputs() const override { return inputs_; }

protected:
  // The light grid and its accumulated grid for `shape`, with `coefficients` per channel.
  void prepareGrids(const GpuBenchShape& shape, int coefficients) {
    shape_ = shape;
    inputs_.clear();
    uploads_.clear();
    for (auto& [name, values] : benchLightGrids(shape.resolution, coefficients))
      addInput(name, std::move(values), name == "current" ? current_ : accumulated_);
  }
  // `values` as input `name`, uploaded into `buffer` (a DualBuffer or gl::Buffer, allocated here).
  template <class Buffer>
  void addInput(const std::string& name, std::vector<float> values, Buffer& buffer) {
    buffer = Buffer(values.size() * sizeof(float), "gpubench " + name);
    inputs_.emplace_back(name, std::move(values));
    uploads_.emplace_back(name, [&buffer](const std::vector<float>& v) {
      buffer.upload(v.data(), v.size() * sizeof(float));
    });
  }
  double cellIterations() const {
    return double(shared::cellCount(shape_.resolution)) * shape_.iterations;
  }

  GpuBenchShape shape_;
  DualBuffer current_, accumulated_;

private:
  GpuBenchInputs inputs_;
  std::vector<std::pair<std::string, std::function<void(const std::vector<float>&)>>> uploads_;
};

}  // namespace lpvlab
