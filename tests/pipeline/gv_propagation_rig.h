#pragma once
// The "standard" propagation strategy on a hand-made light grid and, optionally, a hand-made
// geometry volume, for the occlusion and gather/scatter tests; and the GV lookup of
// shaders/common/geometry_volume_lookup.glsl compiled as double-precision C++ over `gvBlocking`.

#include <memory>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"
#include "pipeline_test_support.h"

// The lookup reads the global `gvBlocking` (the kernels' buffer); the reference sets it.
LPVLAB_SHARED_GLSL_BEGIN
std::vector<double> gvBlocking;
using glm::mix;
#include "shaders/common/geometry_volume_lookup.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab::test {

using Floats = std::vector<float>;

class GvPropagationRig {
public:
  // method: "gather" or "scatter"; withGv: declare the GV (the kernels read it).
  GvPropagationRig(const glm::ivec3& resolution, int shOrder, int iterations,
                   const std::string& method, bool withGv) {
    glTestContext();
    table_.insert("iterations", iterations);
    table_.insert("method", method);
    Params params(table_, "gv propagation test", "propagation");
    strategy_ = Registry<PropagationStrategy>::instance().create(params, "standard");
    params.finish();
    const GridGeometry geometry{glm::vec3(0.0f), 1.0f, resolution};
    Requirements requirements;
    requirements.shOrder = shOrder;
    requirements.geometryVolume = withGv;
    strategy_->declare(requirements);
    strategy_->prepare(shaders_, geometry, requirements);
    grid_ = LightGrid(geometry, requirements.shOrder);
    if (withGv) gv_ = std::make_unique<GeometryVolume>(geometry, false);
  }

  void load(const Floats& current, const Floats& accumulated) {
    grid_.current.upload(current.data(), current.size() * sizeof(float));
    grid_.accumulated.upload(accumulated.data(), accumulated.size() * sizeof(float));
  }
  // The GV's blocking coefficients (geometry_volume.h layout) and its first occluded iteration.
  void loadGv(const Floats& blocking, int firstOccludedIteration) {
    gv_->blocking.upload(blocking.data(), blocking.size() * sizeof(float));
    gv_->firstOccludedIteration = firstOccludedIteration;
  }
  void propagate() {
    Frame frame{.gbuffer = gbuffer_, .lightMaps = lightMaps_, .lightGrid = grid_,
                .indirect = indirect_, .geometryVolume = gv_.get()};
    strategy_->propagate(frame);
    checkGl("gv propagation test");
  }
  Floats current() const { return download(grid_.current); }
  Floats accumulated() const { return download(grid_.accumulated); }
  std::size_t floatsPerGrid() const { return grid_.floatsPerGrid(); }
  std::size_t gvFloats() const { return std::size_t(gv_->geometry.cellCount()) * 4; }

private:
  Floats download(const gl::Buffer& buffer) const {
    Floats data(grid_.floatsPerGrid());
    buffer.download(data.data(), data.size() * sizeof(float));
    return data;
  }
  toml::table table_;
  ShaderCompiler shaders_;
  std::unique_ptr<PropagationStrategy> strategy_;
  LightGrid grid_;
  std::unique_ptr<GeometryVolume> gv_;
  GBuffer gbuffer_;  // propagation reads none of these
  LightMaps lightMaps_;
  gl::Texture indirect_;
};

}  // namespace lpvlab::test
