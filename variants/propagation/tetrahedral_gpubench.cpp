// lpvlab-gpubench's cases of tetrahedral propagation (docs/gpu.md#gpubench): a frame's split,
// `iterations` lattice steps and merge, run by the strategy's own launcher (tetrahedral_gl.h) on
// propagation_gpubench.h's inputs, the GV attenuating from the step at which light has crossed
// one cube on. Units: cube-iterations; their counts are a step's plus the split's and the merge's
// shared over the iterations. The checksum is of the accumulated grid and the last step's light.

#include <memory>
#include <string>

#include "framework/gpubench/gpu_bench_case.h"
#include "variants/propagation/propagation_gpubench.h"
#include "variants/propagation/tetrahedral_gl.h"

namespace lpvlab {
namespace {

class TetrahedralBench final : public PropagationBench {
public:
  explicit TetrahedralBench(bool withGv) { settings_.withGv = withGv; }

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    settings_.coefficients = (shape.shOrder + 1) * (shape.shOrder + 1);
    kernel_ = TetrahedralGlKernel(shaders, settings_, shape.resolution);
    prepareGrids(shape, settings_.coefficients);
    if (settings_.withGv) addInput("gv", benchGvBlocking(shape.resolution), blocking_);
  }

  void run() override {
    kernel_.propagate(shape_.resolution, shape_.iterations, current_, accumulated_, &blocking_, 1);
  }

  GpuBenchWork work() const override {
    const TetrahedralGlWork w = tetrahedralGlWork(settings_);
    const double iterations = shape_.iterations;
    return {"cell-iteration", cellIterations(),
            w.step.multiplyAdds + w.frame.multiplyAdds / iterations,
            w.step.bytes + w.frame.bytes / iterations};
  }

private:
  TetrahedralGlSettings settings_;
  TetrahedralGlKernel kernel_;
  gl::Buffer blocking_;
};

LPVLAB_REGISTER_GPU_BENCH("tetrahedral",
                          "tetrahedral propagation: split, lattice steps (face integrals), merge",
                          "[propagation] type = \"tetrahedral\"",
                          std::make_unique<TetrahedralBench>(false));
LPVLAB_REGISTER_GPU_BENCH("tetrahedral_gv", "tetrahedral propagation with the geometry volume",
                          "[propagation] type = \"tetrahedral\"; [occlusion] type = \"geometry_volume\"",
                          std::make_unique<TetrahedralBench>(true));

}  // namespace
}  // namespace lpvlab
