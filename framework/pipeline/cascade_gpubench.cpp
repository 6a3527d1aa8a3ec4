// lpvlab-gpubench's case of the cascades' carry (docs/gpu.md#gpubench): a child level's injected
// light summed into its parent (restrict.comp) by the pipeline's own CascadeCarry. The parent is a
// grid of the shape's resolution rounded down to a multiple of 4 (at least 4) at the origin with
// cells 1 / resolution.x wide; the child has the same cell counts at half the cell size, centred
// on whole parent cells (as placeCascadeLevels places a snapped level). Both grids hold
// gpu_bench_inputs.h's hashed light; the checksum is of the parent's.

#include <memory>
#include <vector>

#include "framework/gpubench/gpu_bench_case.h"
#include "framework/gpubench/gpu_bench_inputs.h"
#include "framework/pipeline/cascade.h"
#include "framework/pipeline/light_grid.h"

namespace lpvlab {
namespace {

class CascadeCarryBench final : public GpuBenchCase {
public:
  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    const glm::ivec3 res = glm::max(glm::ivec3(4), shape.resolution / 4 * 4);
    const float cell = 1.0f / float(shape.resolution.x);
    parent_ = LightGrid(GridGeometry{glm::vec3(0.0f), cell, res}, shape.shOrder);
    child_ = LightGrid(GridGeometry{glm::vec3(res / 4) * cell, 0.5f * cell, res}, shape.shOrder);
    carry_ = std::make_unique<CascadeCarry>(shaders, shape.shOrder, false);
    coefficients_ = (shape.shOrder + 1) * (shape.shOrder + 1);
    const std::size_t floats = parent_.floatsPerGrid();
    inputs_ = {{"parent", benchValues(floats, 50, -1.0f, 1.0f)},
               {"child", benchValues(floats, 51, -1.0f, 1.0f)}};
  }

  void reset() override {
    parent_.current.upload(inputs_[0].second.data(), inputs_[0].second.size() * sizeof(float));
    child_.current.upload(inputs_[1].second.data(), inputs_[1].second.size() * sizeof(float));
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override { carry_->carry(child_, parent_); }

  double checksum() const override { return benchChecksumOf(parent_.current); }

  GpuBenchWork work() const override {
    const KernelWork w = cascadeCarryGlWork(coefficients_);
    const glm::dvec3 half(parent_.geometry.resolution / 2);
    return {"parent-cell", half.x * half.y * half.z, w.multiplyAdds, w.bytes};
  }

  const GpuBenchInputs& inputs() const override { return inputs_; }

private:
  LightGrid parent_, child_;
  std::unique_ptr<CascadeCarry> carry_;
  int coefficients_ = 4;
  GpuBenchInputs inputs_;
};

LPVLAB_REGISTER_GPU_BENCH("cascade_carry",
                          "the cascades' carry: a child level's light summed into its parent",
                          "[cascades] levels = 2, carry = true",
                          std::make_unique<CascadeCarryBench>());

}  // namespace
}  // namespace lpvlab
