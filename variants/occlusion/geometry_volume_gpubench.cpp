// lpvlab-gpubench's cases of the geometry volume (docs/gpu.md#gpubench), run by the strategy's own
// launcher (geometry_volume_gl.h) into the GV of a light grid at the origin with cells
// 1 / resolution.x wide (the GV: one more cell per axis, half a cell lower, as
// GeometryVolume::placementFor places it):
//   gv_camera: the camera's surfels (gv_camera.comp), a G-buffer of shape.image pixels, every one
//     covered, seen from (0.5, 0.5, -1) with a 60-degree vertical field of view;
//   gv_light: the light views' surfels (gv_rsm.comp), one view's RSM of shape.image.x texels
//     square, the view that buildLightViews gives a directional light travelling along
//     (-0.3, -1, -0.2) over the grid's box.
//   gv_merge: two such GVs (hashed coefficients, c0 in [0, 1.5], with albedo sums) merged cell by
//     cell by the larger c0 (gv_merge.comp), as the camera's and the lights' GVs are and a
//     history is.
// The surfels (gpubench_surfaces.h): points uniform in the grid's box, random unit normals,
// albedo (or flux) in [0, 1]. Their coefficients (and albedo sums) are added with float atomics,
// in any order. The checksum is of the GV (and its albedo sums).

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "framework/gl/resources.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "framework/pipeline/light_views.h"
#include "framework/math/shared.h"
#include "variants/occlusion/geometry_volume_gl.h"
#include "variants/propagation/propagation_gpubench.h"
#include "variants/resources/gpubench_surfaces.h"

namespace lpvlab {
namespace {

// The light whose view gv_light's RSM is, over `box`: what buildLightViews makes of it.
LightViews benchLightViews(const Bounds& box) {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
  return buildLightViews({sun}, box);
}

class GvBench final : public GpuBenchCase {
public:
  GvBench(bool fromLight, bool withAlbedo) : fromLight_(fromLight), withAlbedo_(withAlbedo) {}

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    shape_ = shape;
    kernels_ = GeometryVolumeGlKernels(shaders, !fromLight_, fromLight_, withAlbedo_, false);
    const glm::vec3 extent = glm::vec3(shape.resolution) / float(shape.resolution.x);
    const glm::ivec2 image = fromLight_ ? glm::ivec2(shape.image.x) : shape.image;
    inputs_.clear();
    surfels_.prepare(inputs_, image, extent, {"position", "normal", "albedo"}, fromLight_ ? 40 : 30,
                     fromLight_);
    if (fromLight_) {
      const LightViews records = benchLightViews({glm::vec3(0.0f), extent});
      lightRecords_ = gl::Buffer(records.lights.size() * sizeof(GpuLight), "gpubench lights",
                                 records.lights.data());
      viewRecords_ = gl::Buffer(records.views.size() * sizeof(GpuView), "gpubench views",
                                records.views.data());
    }
    const std::size_t cells = std::size_t(shared::cellCount(gvGeometry().resolution));
    blocking_ = gl::Buffer(4 * cells * sizeof(float), "gpubench GV");
    if (withAlbedo_) albedo_ = gl::Buffer(4 * cells * sizeof(float), "gpubench GV albedo");
  }

  void reset() override {
    surfels_.upload(inputs_);
    blocking_.zero();
    if (withAlbedo_) albedo_.zero();
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override {
    const GvGlSurfels surfels{surfels_.position(), surfels_.normal(), surfels_.colour()};
    const GvGlTarget target{.gv = gvGeometry(), .blocking = &blocking_,
                            .albedo = withAlbedo_ ? &albedo_ : nullptr};
    if (fromLight_)
      kernels_.injectLightViews(surfels, shape_.image.x, 1, lightRecords_, viewRecords_, target);
    else
      kernels_.injectCamera(surfels, shape_.image.x, shape_.image.y, kCamera, texelEdge(), target);
  }

  double checksum() const override {
    return benchChecksumOf(blocking_) + (withAlbedo_ ? benchChecksumOf(albedo_) : 0.0);
  }

  GpuBenchWork work() const override {
    const KernelWork w = gvSurfelGlWork(withAlbedo_);
    return {"surfel", double(shape_.image.x) * (fromLight_ ? shape_.image.x : shape_.image.y),
            w.multiplyAdds, w.bytes};
  }

  const GpuBenchInputs& inputs() const override { return inputs_; }

  static constexpr glm::vec3 kCamera{0.5f, 0.5f, -1.0f};
  static constexpr double kVerticalFovDeg = 60.0;

private:
  GridGeometry gvGeometry() const {
    const float cell = 1.0f / float(shape_.resolution.x);
    return {glm::vec3(-0.5f * cell), cell, shape_.resolution + 1};
  }
  // A pixel's edge at unit depth.
  float texelEdge() const {
    return float(2.0 * std::tan(0.5 * kVerticalFovDeg * M_PI / 180.0) / shape_.image.y);
  }

  bool fromLight_, withAlbedo_;
  GpuBenchShape shape_;
  GeometryVolumeGlKernels kernels_;
  BenchSurfaces surfels_;
  gl::Buffer blocking_, albedo_, lightRecords_, viewRecords_;
  GpuBenchInputs inputs_;
};

// gv_merge: `other` into `target` by the larger c0, with their albedo sums.
class GvMergeBench final : public GpuBenchCase {
public:
  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    kernels_ = GeometryVolumeGlKernels(shaders, false, false, true, true);
    cells_ = std::size_t(shared::cellCount(shape.resolution + 1));
    std::vector<float> target = benchValues(4 * cells_, 60, -1.0f, 1.0f);
    std::vector<float> other = benchValues(4 * cells_, 61, -1.0f, 1.0f);
    for (std::size_t i = 0; i < cells_; ++i) {  // c0 >= 0, as a GV's
      target[i] = 0.75f * (target[i] + 1.0f);
      other[i] = 0.75f * (other[i] + 1.0f);
    }
    inputs_ = {{"target", target}, {"other", other},
               {"target_albedo", benchValues(4 * cells_, 62, 0.0f, 1.0f)},
               {"other_albedo", benchValues(4 * cells_, 63, 0.0f, 1.0f)}};
    for (gl::Buffer* b : {&target_, &other_, &targetAlbedo_, &otherAlbedo_})
      *b = gl::Buffer(4 * cells_ * sizeof(float), "gpubench GV");
  }

  void reset() override {
    gl::Buffer* buffers[] = {&target_, &other_, &targetAlbedo_, &otherAlbedo_};
    for (std::size_t i = 0; i < inputs_.size(); ++i)
      buffers[i]->upload(inputs_[i].second.data(), inputs_[i].second.size() * sizeof(float));
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override { kernels_.merge(target_, other_, &targetAlbedo_, &otherAlbedo_); }

  double checksum() const override {
    return benchChecksumOf(target_) + benchChecksumOf(targetAlbedo_);
  }

  // Per GV cell: both GVs' 4 coefficients and 4 albedo sums read, one compare, the kept 8 written.
  GpuBenchWork work() const override { return {"gv-cell", double(cells_), 1, 4 * 8 * 3}; }

  const GpuBenchInputs& inputs() const override { return inputs_; }

private:
  GeometryVolumeGlKernels kernels_;
  std::size_t cells_ = 0;
  gl::Buffer target_, other_, targetAlbedo_, otherAlbedo_;
  GpuBenchInputs inputs_;
};

LPVLAB_REGISTER_GPU_BENCH("gv_camera", "the geometry volume from the camera's G-buffer surfels",
                          "[occlusion] type = \"geometry_volume\", sources = [\"camera\"]",
                          std::make_unique<GvBench>(false, false));
LPVLAB_REGISTER_GPU_BENCH("gv_camera_albedo",
                          "the camera's surfels with the GV's albedo (for bounces)",
                          "[occlusion] type = \"geometry_volume\", sources = [\"camera\"]; "
                          "[propagation] bounces = true",
                          std::make_unique<GvBench>(false, true));
LPVLAB_REGISTER_GPU_BENCH("gv_light", "the geometry volume from a light view's RSM surfels",
                          "[occlusion] type = \"geometry_volume\", sources = [\"light\"]",
                          std::make_unique<GvBench>(true, false));
LPVLAB_REGISTER_GPU_BENCH("gv_merge", "two geometry volumes merged by the larger c0, with albedo",
                          "[occlusion] type = \"geometry_volume\", history = true",
                          std::make_unique<GvMergeBench>());

}  // namespace
}  // namespace lpvlab
