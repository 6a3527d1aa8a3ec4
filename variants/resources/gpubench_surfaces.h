#pragma once
// Surfaces as the raster passes leave them, for lpvlab-gpubench's cases that read a G-buffer or an
// RSM (gpu_bench_inputs.h's hashed values): per texel of an image, a point uniform in the box
// [0, extent] (w = 1: covered), a random unit normal (w = 1) and a colour in [0, 1] per channel
// (w = 1: the albedo, or an RSM's flux), as RGBA32F texels, bottom row first.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glad/gl.h>
#include <glm/glm.hpp>

#include "framework/gl/resources.h"
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

// Such surfaces as a case's inputs and RGBA32F textures: prepare() makes both, upload() fills the
// textures again before each run.
class BenchSurfaces {
public:
  // Appends benchSurfaceTexels' three inputs to `inputs` and allocates their textures: 2D, or
  // (layered) 2D arrays of one layer, as a light view's RSM.
  void prepare(GpuBenchInputs& inputs, const glm::ivec2& image, const glm::vec3& extent,
               const std::string (&names)[3], std::uint64_t stream, bool layered) {
    image_ = image;
    layered_ = layered;
    for (auto& [name, values] : benchSurfaceTexels(image, extent, names, stream))
      inputs.emplace_back(name, std::move(values));
    for (int i = 0; i < 3; ++i) {
      names_[i] = names[i];
      textures_[i] = gl::Texture(layered ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, GL_RGBA32F, image.x,
                                 image.y, 1, "gpubench " + names[i]);
    }
  }
  void upload(const GpuBenchInputs& inputs) const {
    for (int i = 0; i < 3; ++i) {
      const float* texels = benchInput(inputs, names_[i]).data();
      if (layered_)
        glTextureSubImage3D(textures_[i].id(), 0, 0, 0, 0, image_.x, image_.y, 1, GL_RGBA, GL_FLOAT,
                            texels);
      else
        glTextureSubImage2D(textures_[i].id(), 0, 0, 0, image_.x, image_.y, GL_RGBA, GL_FLOAT,
                            texels);
    }
  }
  GLuint position() const { return textures_[0].id(); }
  GLuint normal() const { return textures_[1].id(); }
  GLuint colour() const { return textures_[2].id(); }

private:
  glm::ivec2 image_{0};
  bool layered_ = false;
  std::string names_[3];
  gl::Texture textures_[3];
};

}  // namespace lpvlab
