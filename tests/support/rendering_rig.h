#pragma once
// A rendering strategy run on a G-buffer (a rendered one, or one row of pixels with chosen
// positions, normals and albedos) and hand-made light grids: one grid, or the levels of a cascade.

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/shared.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"
#include "framework/scene/scene.h"
#include "pipeline_test_support.h"

namespace lpvlab::test {

using glm::dvec3;

struct SurfacePixel {
  dvec3 position;  // world, metres
  dvec3 normal;    // unit
  dvec3 albedo;
};

// A light grid in grid.glsl's layout, with its placement and SH order.
struct HandGrid {
  GridGeometry geometry;
  int order = 1;
  std::vector<float> data;

  HandGrid(const GridGeometry& g, int shOrder)
      : geometry(g), order(shOrder),
        data(std::size_t(3) * coefficients() * g.cellCount(), 0.0f) {}
  int coefficients() const { return shared::shCoefficientCount(order); }
  float& at(glm::ivec3 cell, int channel, int k) {
    return data[shared::coefficientIndex(channel, k, coefficients(),
                                         shared::cellIndex(cell, geometry.resolution),
                                         geometry.cellCount())];
  }
  float at(glm::ivec3 cell, int channel, int k) const {
    return const_cast<HandGrid*>(this)->at(cell, channel, k);
  }
  // f(cell, channel, c) sets the channel's coefficients in `c` (coefficients() zeros on entry);
  // cells in z, y, x order, channels in order.
  template <class F>
  void fill(F f) {
    const glm::ivec3 r = geometry.resolution;
    std::vector<double> c;
    for (int z = 0; z < r.z; ++z)
      for (int y = 0; y < r.y; ++y)
        for (int x = 0; x < r.x; ++x)
          for (int channel = 0; channel < 3; ++channel) {
            c.assign(coefficients(), 0.0);
            f(glm::ivec3(x, y, z), channel, c);
            for (int k = 0; k < coefficients(); ++k) at({x, y, z}, channel, k) = float(c[k]);
          }
  }
};

// Renders the G-buffer `gbuffer` with the strategy `type` and its [rendering] table `table`, from
// the cascade `levels` (finest first, all with the same cell counts and SH order) blended over
// `blendCells` cells; the output is zeroed first, as the pipeline does. `backend` chooses where
// the strategy runs (ComputeBackend::Cpu refuses one without a CPU kernel). Returns the indirect
// radiance per pixel, rows from the bottom.
inline std::vector<dvec3> renderGBuffer(const std::string& type, toml::table table,
                                        const std::vector<HandGrid>& levels, const GBuffer& gbuffer,
                                        const Camera& camera, float blendCells = 0.0f,
                                        ComputeBackend backend = ComputeBackend::Gl) {
  const HandGrid& grid = levels.front();
  test::glTestContext();
  table.insert_or_assign("type", type);
  Params params(table, "rendering test", "rendering");
  std::unique_ptr<RenderingStrategy> rendering =
      Registry<RenderingStrategy>::instance().create(params, "trilinear");
  params.finish();
  Requirements requirements;
  requirements.shOrder = grid.order;
  requirements.backend = backend;
  EXPECT_LE(grid.order, rendering->maxShOrder());
  ShaderCompiler shaders;
  rendering->prepare({.shaders = shaders, .grid = grid.geometry, .requirements = requirements});
  std::vector<LightGrid> lightGrids;
  for (const HandGrid& level : levels) {
    lightGrids.emplace_back(level.geometry, level.order);
    lightGrids.back().accumulated.upload(level.data.data(), level.data.size() * sizeof(float));
  }
  DualImage indirect(gbuffer.width, gbuffer.height, "indirect (test)");  // zeros
  const LightMaps noLightMaps;
  HostReadback host;
  Frame frame{.camera = &camera, .gbuffer = gbuffer, .lightMaps = noLightMaps,
              .lightGrid = lightGrids.front(), .indirect = indirect, .host = &host,
              .levels = lightGrids, .cascadeBlendCells = blendCells};
  rendering->render(frame);
  const HostImage& out = indirect.hostRead();
  checkGl("rendering variants test");
  std::vector<dvec3> result;
  for (std::size_t i = 0; i < std::size_t(gbuffer.width) * std::size_t(gbuffer.height); ++i)
    result.emplace_back(out.texels[i]);
  return result;
}

// renderGBuffer on a G-buffer of one row holding `pixels`, seen from `cameraPosition`.
inline std::vector<dvec3> renderPixels(const std::string& type, toml::table table,
                                       const std::vector<HandGrid>& levels,
                                       const std::vector<SurfacePixel>& pixels,
                                       const glm::vec3& cameraPosition, float blendCells = 0.0f,
                                       ComputeBackend backend = ComputeBackend::Gl) {
  test::glTestContext();
  const int w = int(pixels.size());
  GBuffer gbuffer;
  gbuffer.width = w;
  gbuffer.height = 1;
  std::vector<float> position, normal, albedo;
  for (const SurfacePixel& p : pixels)
    for (int c = 0; c < 4; ++c) {
      position.push_back(c < 3 ? float(p.position[c]) : 1.0f);
      normal.push_back(c < 3 ? float(p.normal[c]) : 1.0f);
      albedo.push_back(c < 3 ? float(p.albedo[c]) : 1.0f);
    }
  auto texture = [&](const std::vector<float>& texels, const char* label) {
    gl::Texture t(GL_TEXTURE_2D, GL_RGBA32F, w, 1, 1, label);
    glTextureSubImage2D(t.id(), 0, 0, 0, w, 1, GL_RGBA, GL_FLOAT, texels.data());
    return t;
  };
  gbuffer.position = texture(position, "position (test)");
  gbuffer.normal = texture(normal, "normal (test)");
  gbuffer.albedo = texture(albedo, "albedo (test)");
  Camera camera;
  camera.position = cameraPosition;
  return renderGBuffer(type, std::move(table), levels, gbuffer, camera, blendCells, backend);
}

inline std::vector<dvec3> renderPixels(const std::string& type, toml::table table, const HandGrid& grid,
                                       const std::vector<SurfacePixel>& pixels,
                                       const glm::vec3& cameraPosition) {
  return renderPixels(type, std::move(table), std::vector<HandGrid>{grid}, pixels, cameraPosition);
}

}  // namespace lpvlab::test
