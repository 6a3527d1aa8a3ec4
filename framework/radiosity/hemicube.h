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
  HemicubeFormFactors(ShaderCompiler& shaders, const PatchMesh& mesh, int resolution, float sceneSize);
  ~HemicubeFormFactors() override;

  void computeRows(const std::vector<std::uint32_t>& sides, FormFactorRows& rows) override;
  std::size_t batch() const override { return std::size_t(tilesX_) * std::size_t(tilesY_); }
  nlohmann::json statistics() const override;
  double work() const override { return double(hemicubes_); }
  std::string workUnit() const override { return "hemicube"; }
  std::size_t memoryBytes() const override;

  const HemicubeMaps& maps() const { return maps_; }

private:
  void renderBatch(const std::uint32_t* sides, std::size_t count);

  const PatchMesh& mesh_;
  HemicubeMaps maps_;
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
