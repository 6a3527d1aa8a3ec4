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

class StandardBench final : public PropagationBench {
public:
  StandardBench(bool scatter, bool tiled, bool withGv, bool bounces)
      : settings_{.farFace = cubeFaceSolidAngles().farFace,
                  .sideFace = cubeFaceSolidAngles().sideFace,
                  .withGv = withGv,
                  .bounces = bounces,
                  .scatter = scatter,
                  .tiled = tiled} {}

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    settings_.coefficients = (shape.shOrder + 1) * (shape.shOrder + 1);
    kernel_ = StandardGlKernel(shaders, settings_);
    prepareGrids(shape, settings_.coefficients);
    scratch_ = DualBuffer(current_.size(), "gpubench light grid (scratch)");
    if (settings_.withGv) addInput("gv", benchGvBlocking(shape.resolution), blocking_);
    if (settings_.bounces) addInput("albedo", benchGvAlbedo(shape.resolution), albedo_);
  }

  void run() override {
    const StandardGlOcclusion occlusion{.blocking = &blocking_, .albedo = &albedo_,
                                        .firstOccludedIteration = 1};
    kernel_.propagate(shape_.resolution, shape_.iterations, current_, scratch_, accumulated_,
                      occlusion);
  }

  GpuBenchWork work() const override {
    const KernelWork w = standardGlKernelWork(settings_);
    return {"cell-iteration", cellIterations(), w.multiplyAdds, w.bytes};
  }

private:
  StandardGlSettings settings_;
  StandardGlKernel kernel_;
  DualBuffer scratch_;
  gl::Buffer blocking_, albedo_;
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
