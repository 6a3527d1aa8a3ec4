#pragma once
// A propagation strategy created as an experiment creates it (by registered name, from a TOML
// table), on its own light grid of a chosen SH order, with the resources the strategy consumes
// (a normal grid, the GV's albedo) and, optionally, a geometry volume; for tests that run a propagation kernel on
// hand-made grids. Also the GV lookup of shaders/common/geometry_volume_lookup.glsl compiled as
// double-precision C++ over `shared::gvBlocking`, and the grid helpers (grid_test_support.h).

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"
#include "variants/resources/geometry_volume.h"
#include "grid_test_support.h"
#include "pipeline_test_support.h"
#include "stand_in_requirements.h"

// The lookup reads the global `gvBlocking` (the kernels' buffer); a reference model sets it.
LPVLAB_SHARED_GLSL_BEGIN
std::vector<double> gvBlocking;
using glm::mix;
#include "shaders/common/geometry_volume_lookup.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab::test {

class PropagationRig {
public:
  // type: the registered strategy name; table: its [propagation] table; withGv: the composition
  // has a geometry volume (the strategy's kernels read it); backend: where its kernels run (the
  // CPU backend reads the rig's GL buffers back and writes them, as in a pipeline).
  PropagationRig(const std::string& type, const glm::ivec3& resolution, toml::table table,
                 int shOrder = 1, bool withGv = false, ComputeBackend backend = ComputeBackend::Gl)
      : table_(std::move(table)) {
    glTestContext();
    Params params(table_, "propagation test", "propagation");
    strategy_ = Registry<PropagationStrategy>::instance().create(params, type);
    params.finish();
    geometry_ = GridGeometry{glm::vec3(0.0f), 1.0f, resolution};
    Requirements requirements = standInRequirements(
        *strategy_, shOrder, withGv ? std::vector<std::string>{std::string(kGeometryVolume.name)}
                                    : std::vector<std::string>{});
    requirements.backend = backend;
    strategy_->prepare({.shaders = shaders_, .grid = geometry_, .requirements = requirements});
    grid_ = LightGrid(geometry_, requirements.shOrder);
    if (requirements.has(kNormalGrid)) {
      normals_ = std::make_unique<NormalGrid>(geometry_);
      resources_.put(kNormalGrid, *normals_);
    }
    if (requirements.has(kGeometryVolume)) {
      gv_ = std::make_unique<GeometryVolume>(geometry_, 0);
      resources_.put(kGeometryVolume, *gv_);
    }
    if (requirements.has(kSurfaceAlbedo)) {
      albedo_ = std::make_unique<SurfaceAlbedo>(geometry_);
      resources_.put(kSurfaceAlbedo, *albedo_);
    }
  }

  void load(const Grid& current, const Grid& accumulated) {
    grid_.current.upload(current.data(), current.size() * sizeof(float));
    grid_.accumulated.upload(accumulated.data(), accumulated.size() * sizeof(float));
  }
  // Both current and accumulated: the grid as injection leaves it.
  void load(const Grid& injected) { load(injected, injected); }
  // The normal grid as injection leaves it: vec4 per cell.
  void loadNormals(const std::vector<float>& normals) {
    ASSERT_TRUE(normals_) << "the strategy declared no normal grid";
    normals_->normals.upload(normals.data(), normals.size() * sizeof(float));
  }
  // The GV's blocking coefficients (geometry_volume.h layout) and its first occluded iteration.
  void loadGv(const std::vector<float>& blocking, int firstOccludedIteration) {
    ASSERT_TRUE(gv_) << "the rig was made without a geometry volume";
    gv_->blocking.upload(blocking.data(), blocking.size() * sizeof(float));
    gv_->firstOccludedIteration = firstOccludedIteration;
  }
  // The GV's albedo (rho A, A per GV cell), when the strategy consumes kSurfaceAlbedo.
  void loadAlbedo(const std::vector<float>& albedo) {
    ASSERT_TRUE(albedo_) << "the strategy consumes no surface albedo";
    albedo_->albedo.upload(albedo.data(), albedo.size() * sizeof(float));
  }
  void propagate() {
    Frame frame{.gbuffer = gbuffer_, .lightMaps = lightMaps_, .lightGrid = grid_,
                .indirect = indirect_, .resources = &resources_};
    strategy_->propagate(frame);
    checkGl("propagation test");
  }
  Grid current() const { return download(grid_.current, floatsPerGrid()); }
  Grid accumulated() const { return download(grid_.accumulated, floatsPerGrid()); }
  std::vector<float> normals() const {
    return download(normals_->normals, std::size_t(4) * geometry_.cellCount());
  }
  std::size_t floatsPerGrid() const { return grid_.floatsPerGrid(); }
  PropagationStrategy& strategy() { return *strategy_; }

private:
  template <class Buffer>  // gl::Buffer or DualBuffer
  static Grid download(const Buffer& buffer, std::size_t floats) {
    Grid data(floats);
    buffer.download(data.data(), data.size() * sizeof(float));
    return data;
  }
  toml::table table_;
  ShaderCompiler shaders_;
  std::unique_ptr<PropagationStrategy> strategy_;
  GridGeometry geometry_;
  LightGrid grid_;
  std::unique_ptr<NormalGrid> normals_;
  std::unique_ptr<GeometryVolume> gv_;
  std::unique_ptr<SurfaceAlbedo> albedo_;
  ResourceTable resources_;  // borrows the three above
  GBuffer gbuffer_;  // propagation reads none of these
  LightMaps lightMaps_;
  DualImage indirect_;
};

// A [propagation] table: `iterations`, and `method` unless empty.
inline toml::table iterationsTable(int iterations, const std::string& method = "") {
  toml::table t;
  t.insert("iterations", iterations);
  if (!method.empty()) t.insert("method", method);
  return t;
}

}  // namespace lpvlab::test
