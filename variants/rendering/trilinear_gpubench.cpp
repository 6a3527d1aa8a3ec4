// lpvlab-gpubench's cases of trilinear rendering (docs/gpu.md#gpubench): the kernel run by the
// strategies' own launcher (trilinear_gl.h) over an image of shape.image pixels and one light
// grid at the origin with cells 1 / resolution.x wide (so it spans 1 m along x). The G-buffer
// (gpu_bench_inputs.h's hashed values): surface points uniform in the grid's box, random unit
// normals, albedo in [0, 1]; the grid's coefficients in [-1, 1]. The checksum is of the indirect
// image's RGB.

#include <memory>
#include <string>
#include <vector>

#include "framework/gl/resources.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "variants/propagation/propagation_gpubench.h"
#include "variants/resources/gpubench_surfaces.h"
#include "variants/rendering/trilinear_gl.h"

namespace lpvlab {
namespace {

class TrilinearBench final : public GpuBenchCase {
public:
  explicit TrilinearBench(float leakDamping) { options_.leakDamping = leakDamping; }

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    shape_ = shape;
    const int coefficients = (shape.shOrder + 1) * (shape.shOrder + 1);
    kernel_ = TrilinearGlKernel(shaders, options_, coefficients);
    coefficients_ = coefficients;
    inputs_.clear();
    gbuffer_.prepare(inputs_, shape.image, glm::vec3(shape.resolution) / float(shape.resolution.x),
                     {"position", "normal", "albedo"}, 10, false);
    const std::vector<float> grid = benchLightGrids(shape.resolution, coefficients)[1].second;
    inputs_.emplace_back("accumulated", grid);
    accumulated_ = DualBuffer(grid.size() * sizeof(float), "gpubench light grid (accumulated)");
    indirect_ = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, shape.image.x, shape.image.y, 1,
                            "gpubench indirect");
  }

  void reset() override {
    const std::vector<float>& grid = benchInput(inputs_, "accumulated");
    accumulated_.upload(grid.data(), grid.size() * sizeof(float));
    gbuffer_.upload(inputs_);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(indirect_.id(), 0, GL_RGBA, GL_FLOAT, zero);
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override {
    const TrilinearGlLevel level{&accumulated_, gridGeometry()};
    kernel_.render({.position = gbuffer_.position(), .normal = gbuffer_.normal(), .albedo = gbuffer_.colour(),
                    .indirect = indirect_.id(), .width = shape_.image.x, .height = shape_.image.y},
                   {&level, 1}, 0.0f, glm::vec3(0.5f, 0.5f, -1.0f));
  }

  double checksum() const override {
    const std::size_t pixels = std::size_t(shape_.image.x) * shape_.image.y;
    std::vector<float> rgba(4 * pixels), rgb;
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glGetTextureImage(indirect_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)),
                      rgba.data());
    for (std::size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) rgb.push_back(rgba[4 * i + c]);
    return benchChecksum(rgb);
  }

  GpuBenchWork work() const override {
    const TrilinearGlWork w = trilinearGlWork(options_, coefficients_);
    return {"pixel", double(shape_.image.x) * shape_.image.y, w.pixelMultiplyAdds, w.pixelBytes};
  }

  const GpuBenchInputs& inputs() const override { return inputs_; }

  GridGeometry gridGeometry() const {
    return {glm::vec3(0.0f), 1.0f / float(shape_.resolution.x), shape_.resolution};
  }

  TrilinearKernelOptions options_;
  GpuBenchShape shape_;
  int coefficients_ = 4;
  TrilinearGlKernel kernel_;
  DualBuffer accumulated_;
  BenchSurfaces gbuffer_;
  gl::Texture indirect_;
  GpuBenchInputs inputs_;
};

LPVLAB_REGISTER_GPU_BENCH("trilinear", "trilinear rendering from one light grid",
                          "[rendering] type = \"trilinear\"",
                          std::make_unique<TrilinearBench>(0.0f));
LPVLAB_REGISTER_GPU_BENCH("trilinear_leak_damping", "trilinear rendering with leak damping",
                          "[rendering] type = \"trilinear\", leak_damping = 1",
                          std::make_unique<TrilinearBench>(1.0f));

}  // namespace
}  // namespace lpvlab
