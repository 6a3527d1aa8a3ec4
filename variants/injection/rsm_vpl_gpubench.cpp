// lpvlab-gpubench's cases of RSM injection (docs/gpu.md#gpubench): the kernel run by the
// strategy's own launcher (rsm_vpl_gl.h) over one view's RSMs of shape.image.x texels square into
// a light grid at the origin with cells 1 / resolution.x wide. The RSM texels
// (gpu_bench_inputs.h's hashed values): points uniform in the grid's box, random unit normals,
// flux in [0, 1] per channel. The grid (and the normal grid) start at zero; the VPLs are added
// with float atomics, in any order. The checksum is of the grid and the normal grid.

#include <memory>
#include <string>
#include <vector>

#include "framework/gl/resources.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "framework/math/shared.h"
#include "variants/injection/rsm_vpl_gl.h"
#include "variants/propagation/propagation_gpubench.h"
#include "variants/resources/gpubench_surfaces.h"

namespace lpvlab {
namespace {

class RsmVplBench final : public GpuBenchCase {
public:
  explicit RsmVplBench(bool withNormals) : withNormals_(withNormals) {}

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    shape_ = shape;
    coefficients_ = (shape.shOrder + 1) * (shape.shOrder + 1);
    kernel_ = RsmVplGlKernel(shaders, coefficients_, withNormals_, 1.0f);
    const int side = shape.image.x;
    // The RSM's normals' w is unused, its flux's w = 1: covered.
    inputs_.clear();
    rsm_.prepare(inputs_, {side, side}, glm::vec3(shape.resolution) / float(shape.resolution.x),
                 {"rsm_position", "rsm_normal", "rsm_flux"}, 20, true);
    const std::size_t cells = std::size_t(shared::cellCount(shape.resolution));
    grid_ = DualBuffer(3 * coefficients_ * cells * sizeof(float), "gpubench light grid");
    if (withNormals_) normals_ = gl::Buffer(4 * cells * sizeof(float), "gpubench normal grid");
  }

  void reset() override {
    rsm_.upload(inputs_);
    grid_.zero();
    if (withNormals_) normals_.zero();
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override {
    kernel_.inject({.position = rsm_.position(), .normal = rsm_.normal(), .flux = rsm_.colour(),
                    .resolution = shape_.image.x, .views = 1},
                   {glm::vec3(0.0f), 1.0f / float(shape_.resolution.x), shape_.resolution}, grid_,
                   &normals_);
  }

  double checksum() const override {
    return benchChecksumOf(grid_) + (withNormals_ ? benchChecksumOf(normals_) : 0.0);
  }

  GpuBenchWork work() const override {
    const KernelWork w = rsmVplGlWork(coefficients_, withNormals_);
    return {"VPL", double(shape_.image.x) * shape_.image.x, w.multiplyAdds, w.bytes};
  }

  const GpuBenchInputs& inputs() const override { return inputs_; }

private:
  bool withNormals_;
  GpuBenchShape shape_;
  int coefficients_ = 4;
  RsmVplGlKernel kernel_;
  BenchSurfaces rsm_;
  DualBuffer grid_;
  gl::Buffer normals_;
  GpuBenchInputs inputs_;
};

LPVLAB_REGISTER_GPU_BENCH("rsm_vpl", "RSM injection: an --image-square RSM's texels as VPLs",
                          "[injection] type = \"rsm_vpl\"", std::make_unique<RsmVplBench>(false));
LPVLAB_REGISTER_GPU_BENCH("rsm_vpl_normals",
                          "RSM injection with the VPLs' normals (for directed propagation)",
                          "[injection] type = \"rsm_vpl\"; [propagation] type = \"directed\"",
                          std::make_unique<RsmVplBench>(true));

}  // namespace
}  // namespace lpvlab
