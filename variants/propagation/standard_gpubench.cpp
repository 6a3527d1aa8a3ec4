// lpvlab-gpubench's cases of standard propagation (docs/gpu.md#gpubench): the strategy's GL
// kernels run by its own launcher (standard_gl.h) on deterministic inputs: a random light grid
// (coefficients in [-1, 1], so the kernels' clamps act), its accumulated grid, and with the GV a
// random blocking potential (c0 in [0, 1.5], band 1 in [-1, 1], as the tests' randomGv) and
// albedo, the GV attenuating from the second iteration on as GeometryVolume's producers set it.
// The checksum is of the accumulated grid and of the last step's light.

#include <memory>
#include <string>
#include <utility>

#include "framework/gl/dual_buffer.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "framework/gpubench/gpu_bench_inputs.h"
#include "framework/math/solid_angle.h"
#include "variants/propagation/standard_gl.h"

namespace lpvlab {
namespace {

class StandardBench final : public GpuBenchCase {
public:
  StandardBench(bool scatter, bool tiled, bool withGv, bool bounces)
      : settings_{.farFace = cubeFaceSolidAngles().farFace,
                  .sideFace = cubeFaceSolidAngles().sideFace,
                  .withGv = withGv,
                  .bounces = bounces,
                  .scatter = scatter,
                  .tiled = tiled} {}

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    shape_ = shape;
    settings_.coefficients = (shape.shOrder + 1) * (shape.shOrder + 1);
    kernel_ = StandardGlKernel(shaders, settings_);
    const glm::ivec3 res = shape.resolution;
    const std::size_t cells = std::size_t(res.x) * res.y * res.z;
    const std::size_t floats = 3 * settings_.coefficients * cells;
    const std::size_t gvCells = std::size_t(res.x + 1) * (res.y + 1) * (res.z + 1);
    inputs_ = {{"current", benchValues(floats, 1, -1.0f, 1.0f)},
               {"accumulated", benchValues(floats, 2, -1.0f, 1.0f)}};
    for (DualBuffer* b : {&current_, &scratch_, &accumulated_})
      *b = DualBuffer(floats * sizeof(float), "gpubench light grid");
    if (settings_.withGv) {
      std::vector<float> gv = benchValues(4 * gvCells, 3, -1.0f, 1.0f);
      for (std::size_t i = 0; i < gvCells; ++i) gv[i] = 0.75f * (gv[i] + 1.0f);  // c0 >= 0
      inputs_.emplace_back("gv", std::move(gv));
      blocking_ = gl::Buffer(4 * gvCells * sizeof(float), "gpubench GV");
    }
    if (settings_.bounces) {
      inputs_.emplace_back("albedo", albedo(gvCells));
      albedo_ = gl::Buffer(4 * gvCells * sizeof(float), "gpubench GV albedo");
    }
  }

  void reset() override {
    for (const auto& [name, values] : inputs_) {
      const std::size_t bytes = values.size() * sizeof(float);
      if (name == "current") current_.upload(values.data(), bytes);
      if (name == "accumulated") accumulated_.upload(values.data(), bytes);
      if (name == "gv") blocking_.upload(values.data(), bytes);
      if (name == "albedo") albedo_.upload(values.data(), bytes);
    }
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override {
    const StandardGlOcclusion occlusion{.blocking = &blocking_, .albedo = &albedo_,
                                        .firstOccludedIteration = 1};
    kernel_.propagate(shape_.resolution, shape_.iterations, current_, scratch_, accumulated_,
                      occlusion);
  }

  double checksum() const override {
    std::vector<float> values(current_.size() / sizeof(float));
    accumulated_.download(values.data(), current_.size());
    double sum = benchChecksum(values);
    current_.download(values.data(), current_.size());
    return sum + benchChecksum(values);
  }

  GpuBenchWork work() const override {
    const StandardTransferWork w = standardGlKernelWork(settings_);
    const glm::dvec3 res(shape_.resolution);
    return {"cell-iteration", res.x * res.y * res.z * shape_.iterations, w.multiplyAdds, w.bytes};
  }

  const GpuBenchInputs& inputs() const override { return inputs_; }

private:
  // (rho A, A) per GV cell: A in [0.1, 1], rho in [0, 1] per channel.
  static std::vector<float> albedo(std::size_t gvCells) {
    const std::vector<float> area = benchValues(gvCells, 4, 0.1f, 1.0f);
    const std::vector<float> rho = benchValues(3 * gvCells, 5, 0.0f, 1.0f);
    std::vector<float> out(4 * gvCells);
    for (std::size_t i = 0; i < gvCells; ++i) {
      for (int c = 0; c < 3; ++c) out[4 * i + c] = area[i] * rho[3 * i + c];
      out[4 * i + 3] = area[i];
    }
    return out;
  }

  StandardGlSettings settings_;
  GpuBenchShape shape_;
  StandardGlKernel kernel_;
  DualBuffer current_, scratch_, accumulated_;
  gl::Buffer blocking_, albedo_;
  GpuBenchInputs inputs_;
};

#define STANDARD_CASE(name, description, settings, scatter, tiled, gv, bounces)               \
  LPVLAB_REGISTER_GPU_BENCH(name, description, "[propagation] type = \"standard\", " settings, \
                            std::make_unique<StandardBench>(scatter, tiled, gv, bounces))

STANDARD_CASE("standard_gather", "standard propagation by gathering (4x4x4 groups)",
              "method = \"gather\"", false, false, false, false);
STANDARD_CASE("standard_gather_tiled", "the tiled gather: x-long tiles in shared memory",
              "gpu_kernel = \"tiled\"", false, true, false, false);
STANDARD_CASE("standard_scatter", "standard propagation by scattering (float atomics)",
              "method = \"scatter\"", true, false, false, false);
STANDARD_CASE("standard_gather_gv", "gathering attenuated by the geometry volume",
              "method = \"gather\"; [occlusion] type = \"geometry_volume\"", false, false, true,
              false);
STANDARD_CASE("standard_gather_tiled_gv", "the tiled gather with the geometry volume",
              "gpu_kernel = \"tiled\"; [occlusion] type = \"geometry_volume\"", false, true, true,
              false);
STANDARD_CASE("standard_scatter_gv", "scattering attenuated by the geometry volume",
              "method = \"scatter\"; [occlusion] type = \"geometry_volume\"", true, false, true,
              false);
STANDARD_CASE("standard_gather_gv_bounces", "gathering with the GV and its bounces",
              "bounces = true; [occlusion] type = \"geometry_volume\"", false, false, true, true);
STANDARD_CASE("standard_gather_tiled_gv_bounces", "the tiled gather with the GV and its bounces",
              "gpu_kernel = \"tiled\", bounces = true; [occlusion] type = \"geometry_volume\"",
              false, true, true, true);

}  // namespace
}  // namespace lpvlab
