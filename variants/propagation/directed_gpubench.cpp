// lpvlab-gpubench's cases of directed propagation (docs/gpu.md#gpubench): the dilation, the
// reprojecting gather, the release and the free light's gather, run by the strategy's own launcher
// (directed_gl.h) with its default settings on propagation_gpubench.h's inputs and an injected
// normal grid in which a third of the cells hold VPLs (a random flux-weighted normal, flux in
// [0.1, 1]) and the rest none, so that the dilation has cells to fill. The GV attenuates from the
// second iteration on. The checksum is of the accumulated grid and the last step's light.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "framework/gpubench/gpu_bench_case.h"
#include "framework/math/shared.h"
#include "variants/propagation/directed_gl.h"
#include "variants/propagation/propagation_gpubench.h"

namespace lpvlab {
namespace {

// vec4 per cell: sum of flux times normal, and flux; zero where no VPL landed.
std::vector<float> benchNormals(const glm::ivec3& resolution) {
  const std::size_t cells = std::size_t(shared::cellCount(resolution));
  const std::vector<float> landed = benchValues(cells, 6, 0.0f, 1.0f);
  const std::vector<float> flux = benchValues(cells, 7, 0.1f, 1.0f);
  const std::vector<float> direction = benchValues(2 * cells, 8, 0.0f, 1.0f);
  std::vector<float> normals(4 * cells, 0.0f);
  for (std::size_t i = 0; i < cells; ++i) {
    if (landed[i] >= 1.0f / 3.0f) continue;
    const double z = 2.0 * direction[2 * i] - 1.0, phi = 2.0 * M_PI * direction[2 * i + 1];
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const glm::dvec3 n(r * std::cos(phi), r * std::sin(phi), z);
    for (int c = 0; c < 3; ++c) normals[4 * i + c] = float(flux[i] * n[c]);
    normals[4 * i + 3] = flux[i];
  }
  return normals;
}

class DirectedBench final : public PropagationBench {
public:
  DirectedBench(bool withGv, bool tiled) {
    settings_.withGv = withGv;
    settings_.tiled = tiled;
    settings_.cosRegionAngle = std::cos(10.0 * M_PI / 180.0);  // the strategy's default
  }

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    settings_.coefficients = (shape.shOrder + 1) * (shape.shOrder + 1);
    kernel_ = DirectedGlKernel(shaders, settings_, shape.resolution);
    prepareGrids(shape, settings_.coefficients);
    addInput("normals", benchNormals(shape.resolution), normals_);
    if (settings_.withGv) addInput("gv", benchGvBlocking(shape.resolution), blocking_);
  }

  void run() override {
    kernel_.propagate(shape_.resolution, shape_.iterations, current_, accumulated_, normals_,
                      &blocking_, 1);
  }

  GpuBenchWork work() const override {
    const KernelWork w = directedGlWork(settings_);
    return {"cell-iteration", cellIterations(), w.multiplyAdds, w.bytes};
  }

private:
  DirectedGlSettings settings_;
  DirectedGlKernel kernel_;
  gl::Buffer normals_, blocking_;
};

LPVLAB_REGISTER_GPU_BENCH("directed",
                          "directed propagation: dilation, reprojecting gather, release, free light",
                          "[propagation] type = \"directed\"",
                          std::make_unique<DirectedBench>(false, false));
LPVLAB_REGISTER_GPU_BENCH("directed_gv", "directed propagation with the geometry volume",
                          "[propagation] type = \"directed\"; [occlusion] type = \"geometry_volume\"",
                          std::make_unique<DirectedBench>(true, false));
LPVLAB_REGISTER_GPU_BENCH("directed_tiled", "directed propagation, its gathers tiled",
                          "[propagation] type = \"directed\", gpu_kernel = \"tiled\"",
                          std::make_unique<DirectedBench>(false, true));
LPVLAB_REGISTER_GPU_BENCH("directed_tiled_gv", "directed propagation, tiled, with the GV",
                          "[propagation] type = \"directed\", gpu_kernel = \"tiled\"; "
                          "[occlusion] type = \"geometry_volume\"",
                          std::make_unique<DirectedBench>(true, true));

}  // namespace
}  // namespace lpvlab
