#pragma once
// Surfaces as the raster passes leave them, for lpvlab-gpubench's cases that read a G-buffer or an
// RSM (gpu_bench_inputs.h's hashed values): per texel of an image, a point uniform in the box
// [0, extent] (w = 1: covered), a random unit normal (w = 1) and a colour in [0, 1] per channel
// (w = 1: the albedo, or an RSM's flux), as RGBA32F texels, bottom row first.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "framework/gpubench/gpu_bench_case.h"
#include "framework/gpubench/gpu_bench_inputs.h"

namespace lpvlab {

// Three inputs named `names` (position, normal, colour), from hash streams stream .. stream + 2.
inline GpuBenchInputs benchSurfaceTexels(const glm::ivec2& image, const glm::vec3& extent,
                                         const std::string (&names)[3], std::uint64_t stream) {
  const std::size_t texels = std::size_t(image.x) * image.y;
  const std::vector<float> p = benchValues(3 * texels, stream, 0.0f, 1.0f);
  const std::vector<float> d = benchValues(2 * texels, stream + 1, 0.0f, 1.0f);
  const std::vector<float> a = benchValues(3 * texels, stream + 2, 0.0f, 1.0f);
  std::vector<float> position(4 * texels, 1.0f), normal(4 * texels, 1.0f), colour(4 * texels, 1.0f);
  for (std::size_t i = 0; i < texels; ++i) {
    const double z = 2.0 * d[2 * i] - 1.0, phi = 2.0 * M_PI * d[2 * i + 1];
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const glm::dvec3 n(r * std::cos(phi), r * std::sin(phi), z);
    for (int c = 0; c < 3; ++c) {
      position[4 * i + c] = p[3 * i + c] * extent[c];
      normal[4 * i + c] = float(n[c]);
      colour[4 * i + c] = a[3 * i + c];
    }
  }
  return {{names[0], position}, {names[1], normal}, {names[2], colour}};
}

}  // namespace lpvlab
