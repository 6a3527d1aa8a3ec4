#pragma once
// Form factors by the hemicube on GL, as seed 004 builds them (3.5-3.7): from the centroid of a
// patch side, five views through the faces of a unit hemicube over it (one full, up the side's
// normal, and four halves, sideways with the normal up, 90 degree fields of view), every patch
// drawn with its index into an item buffer (shaders/radiosity/hemicube.*), each pixel's delta form
// factor (hemicube_maps.h) summed per side seen. The depth test (reversed: depth = near / distance
// in a 32-bit float buffer, precise at every distance) keeps the nearest surface; the near plane,
// 1e-5 of the scene's size, clips the patch's own plane, so neither it nor coplanar neighbours
// are seen and no adjacent wall is cut away (the seed's "parasitic bright rims", 3.6.2).
//
// Hemicubes of many sides are rendered into tiles of one atlas and read back together: one
// GL-to-host transfer per batch, not per view.
//
// Where a side's hemicubes stand (HemicubePlacement; the radiosity method's hemicube_placement):
//   centroid  one, at the centroid, "up" of its top view towards corner 0 (the seed's)
//   vertices  three, at the corners (fig. 3.10), each pulled 1% of the way to the centroid so that
//             it stands inside the patch; the row is their mean: the three-point (vertex) rule for
//             the area-to-area factor, exact where the point factor is linear over the patch
//   jittered  one, at a uniformly random point of the patch, turned about the normal by a random
//             angle (per side, from the stream (seed, side)): the point-to-area factor of a random
//             point, whose expectation is the area-to-area factor, and the item buffer's aliasing
//             differs from side to side instead of repeating
enum class HemicubePlacement { Centroid, Vertices, Jittered };

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/radiosity/form_factors.h"
#include "framework/radiosity/hemicube_maps.h"
#include "framework/radiosity/patches.h"

namespace lpvlab {

class HemicubeFormFactors : public FormFactorEstimator {
public:
  // `mesh` must outlive the estimator. Needs the GL context current (here and in computeRows).
  HemicubeFormFactors(ShaderCompiler& shaders, const PatchMesh& mesh, int resolution, float sceneSize,
                      HemicubePlacement placement = HemicubePlacement::Centroid, std::uint64_t seed = 1);
  ~HemicubeFormFactors() override;

  void computeRows(const std::vector<std::uint32_t>& sides, FormFactorRows& rows) override;
  // Sides per batch: the atlas's tiles over the hemicubes each side takes.
  std::size_t batch() const override {
    return std::max<std::size_t>(1, std::size_t(tilesX_) * std::size_t(tilesY_) / std::size_t(viewsPerSide()));
  }
  nlohmann::json statistics() const override;
  double work() const override { return double(hemicubes_); }
  std::string workUnit() const override { return "hemicube"; }
  std::size_t memoryBytes() const override;

  const HemicubeMaps& maps() const { return maps_; }

private:
  // One hemicube: where it stands and its top view's "up" (unit, in the side's plane).
  struct View {
    glm::vec3 eye, up;
  };
  int viewsPerSide() const { return placement_ == HemicubePlacement::Vertices ? 3 : 1; }
  // The hemicubes of a side, placed as placement_ says.
  void viewsOf(std::uint32_t side, View* views) const;
  void renderBatch(const std::uint32_t* sides, std::size_t count);

  const PatchMesh& mesh_;
  HemicubeMaps maps_;
  HemicubePlacement placement_;
  std::uint64_t seed_;
  Program program_;
  GLuint vertexArray_ = 0;
  gl::Buffer vertices_;
  gl::Texture items_, depth_;
  gl::Framebuffer framebuffer_;
  int tilesX_ = 1, tilesY_ = 1;
  float near_ = 0.0f;
  std::vector<std::uint32_t> readback_;
  std::size_t hemicubes_ = 0;
};

}  // namespace lpvlab
