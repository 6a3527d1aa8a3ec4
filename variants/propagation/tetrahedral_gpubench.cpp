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

class TetrahedralBench final : public GpuBenchCase {
public:
  explicit TetrahedralBench(bool withGv) { settings_.withGv = withGv; }

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    shape_ = shape;
    settings_.coefficients = (shape.shOrder + 1) * (shape.shOrder + 1);
    kernel_ = TetrahedralGlKernel(shaders, settings_, shape.resolution);
    inputs_ = benchLightGrids(shape.resolution, settings_.coefficients);
    const std::size_t bytes = inputs_[0].second.size() * sizeof(float);
    current_ = DualBuffer(bytes, "gpubench light grid");
    accumulated_ = DualBuffer(bytes, "gpubench light grid (accumulated)");
    if (settings_.withGv) {
      inputs_.emplace_back("gv", benchGvBlocking(shape.resolution));
      blocking_ = gl::Buffer(inputs_.back().second.size() * sizeof(float), "gpubench GV");
    }
  }

  void reset() override {
    for (auto [buffer, name] : {std::pair{&current_, "current"}, {&accumulated_, "accumulated"}}) {
      const std::vector<float>& values = benchInput(inputs_, name);
      buffer->upload(values.data(), values.size() * sizeof(float));
    }
    if (settings_.withGv) {
      const std::vector<float>& gv = benchInput(inputs_, "gv");
      blocking_.upload(gv.data(), gv.size() * sizeof(float));
    }
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override {
    kernel_.propagate(shape_.resolution, shape_.iterations, current_, accumulated_, &blocking_, 1);
  }

  double checksum() const override { return benchGridChecksum(accumulated_, current_); }

  GpuBenchWork work() const override {
    const TetrahedralGlWork w = tetrahedralGlWork(settings_);
    const double iterations = shape_.iterations;
    return {"cell-iteration", double(benchCells(shape_.resolution)) * iterations,
            w.step.multiplyAdds + w.frame.multiplyAdds / iterations,
            w.step.bytes + w.frame.bytes / iterations};
  }

  const GpuBenchInputs& inputs() const override { return inputs_; }

private:
  TetrahedralGlSettings settings_;
  GpuBenchShape shape_;
  TetrahedralGlKernel kernel_;
  DualBuffer current_, accumulated_;
  gl::Buffer blocking_;
  GpuBenchInputs inputs_;
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
