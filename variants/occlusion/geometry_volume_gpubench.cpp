// lpvlab-gpubench's cases of the geometry volume (docs/gpu.md#gpubench): the camera's surfels
// (gv_camera.comp) run by the strategy's own launcher (geometry_volume_gl.h) over a G-buffer of
// shape.image pixels, every one covered, into the GV of a light grid at the origin with cells
// 1 / resolution.x wide (the GV: one more cell per axis, half a cell lower, as
// GeometryVolume::placementFor places it), seen from (0.5, 0.5, -1) with a 60-degree vertical field
// of view. The surfels (gpu_bench_inputs.h's hashed values): points uniform in the grid's box,
// random unit normals, albedo in [0, 1]. Their coefficients (and albedo sums) are added with float
// atomics, in any order. The checksum is of the GV (and its albedo sums).

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "framework/gl/resources.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "variants/occlusion/geometry_volume_gl.h"
#include "variants/propagation/propagation_gpubench.h"
#include "variants/resources/gpubench_surfaces.h"

namespace lpvlab {
namespace {

class GvCameraBench final : public GpuBenchCase {
public:
  explicit GvCameraBench(bool withAlbedo) : withAlbedo_(withAlbedo) {}

  void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) override {
    shape_ = shape;
    kernels_ = GeometryVolumeGlKernels(shaders, true, false, withAlbedo_, false);
    inputs_ = benchSurfaceTexels(shape.image, glm::vec3(shape.resolution) / float(shape.resolution.x),
                                 {"position", "normal", "albedo"}, 30);
    for (gl::Texture* t : {&position_, &normal_, &albedoSource_})
      *t = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, shape.image.x, shape.image.y, 1, "gpubench G-buffer");
    const std::size_t cells = benchCells(gvGeometry().resolution);
    blocking_ = gl::Buffer(4 * cells * sizeof(float), "gpubench GV");
    if (withAlbedo_) albedo_ = gl::Buffer(4 * cells * sizeof(float), "gpubench GV albedo");
  }

  void reset() override {
    for (auto [texture, name] : {std::pair{&position_, "position"}, {&normal_, "normal"},
                                 {&albedoSource_, "albedo"}})
      glTextureSubImage2D(texture->id(), 0, 0, 0, shape_.image.x, shape_.image.y, GL_RGBA, GL_FLOAT,
                          benchInput(inputs_, name).data());
    blocking_.zero();
    if (withAlbedo_) albedo_.zero();
    glFinish();  // the uploads are not the kernel's time
  }

  void run() override {
    kernels_.injectCamera({position_.id(), normal_.id(), albedoSource_.id()}, shape_.image.x,
                          shape_.image.y, kCamera, texelEdge(),
                          {.gv = gvGeometry(), .blocking = &blocking_,
                           .albedo = withAlbedo_ ? &albedo_ : nullptr});
  }

  double checksum() const override {
    std::vector<float> values(blocking_.size() / sizeof(float));
    blocking_.download(values.data(), blocking_.size());
    double sum = benchChecksum(values);
    if (withAlbedo_) {
      albedo_.download(values.data(), albedo_.size());
      sum += benchChecksum(values);
    }
    return sum;
  }

  GpuBenchWork work() const override {
    const StandardTransferWork w = gvSurfelGlWork(withAlbedo_);
    return {"surfel", double(shape_.image.x) * shape_.image.y, w.multiplyAdds, w.bytes};
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

  bool withAlbedo_;
  GpuBenchShape shape_;
  GeometryVolumeGlKernels kernels_;
  gl::Texture position_, normal_, albedoSource_;
  gl::Buffer blocking_, albedo_;
  GpuBenchInputs inputs_;
};

LPVLAB_REGISTER_GPU_BENCH("gv_camera", "the geometry volume from the camera's G-buffer surfels",
                          "[occlusion] type = \"geometry_volume\", sources = [\"camera\"]",
                          std::make_unique<GvCameraBench>(false));
LPVLAB_REGISTER_GPU_BENCH("gv_camera_albedo",
                          "the camera's surfels with the GV's albedo (for bounces)",
                          "[occlusion] type = \"geometry_volume\", sources = [\"camera\"]; "
                          "[propagation] bounces = true",
                          std::make_unique<GvCameraBench>(true));

}  // namespace
}  // namespace lpvlab
