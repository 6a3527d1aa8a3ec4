// lpvlab-gpubench's cases of standard propagation (docs/gpu.md#gpubench): the strategy's GL
// kernels run by its own launcher (standard_gl.h) on propagation_gpubench.h's inputs, the GV
// attenuating from the second iteration on as GeometryVolume's producers set it. The checksum is
// of the accumulated grid and of the last step's light.

#include <memory>
#include <string>
#include <utility>

#include "framework/gl/dual_buffer.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "framework/gpubench/gpu_bench_inputs.h"
#include "variants/propagation/propagation_gpubench.h"
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
    inputs_ = benchLightGrids(shape.resolution, settings_.coefficients);
    const std::size_t bytes = inputs_[0].second.size() * sizeof(float);
    for (DualBuffer* b : {&current_, &scratch_, &accumulated_})
      *b = DualBuffer(bytes, "gpubench light grid");
    if (settings_.withGv) {
      inputs_.emplace_back("gv", benchGvBlocking(shape.resolution));
      blocking_ = gl::Buffer(inputs_.back().second.size() * sizeof(float), "gpubench GV");
    }
    if (settings_.bounces) {
      inputs_.emplace_back("albedo", benchGvAlbedo(shape.resolution));
      albedo_ = gl::Buffer(inputs_.back().second.size() * sizeof(float), "gpubench GV albedo");
    }
  }

  void reset() override {
    upload(current_, "current");
    upload(accumulated_, "accumulated");
    if (settings_.withGv) upload(blocking_, "gv");
    if (settings_.bounces) upload(albedo_, "albedo");
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override {
    const StandardGlOcclusion occlusion{.blocking = &blocking_, .albedo = &albedo_,
                                        .firstOccludedIteration = 1};
    kernel_.propagate(shape_.resolution, shape_.iterations, current_, scratch_, accumulated_,
                      occlusion);
  }

  double checksum() const override { return benchGridChecksum(accumulated_, current_); }

  GpuBenchWork work() const override {
    const StandardTransferWork w = standardGlKernelWork(settings_);
    return {"cell-iteration", double(benchCells(shape_.resolution)) * shape_.iterations,
            w.multiplyAdds, w.bytes};
  }

  const GpuBenchInputs& inputs() const override { return inputs_; }

private:
  template <class Buffer>
  void upload(Buffer& buffer, const char* name) {
    const std::vector<float>& values = benchInput(inputs_, name);
    buffer.upload(values.data(), values.size() * sizeof(float));
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
