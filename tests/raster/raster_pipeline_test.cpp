// Whole frames with the raster passes by ray casting (framework/raster) against GL's, on the
// Cornell box (no texture, so every texel of every pass is GL's: ray_raster_passes_test.cpp):
//   - with the strategies on the CPU (the images reach them through the host, never read back
//     from GL) and with the strategies on GL (the images uploaded to GL's textures), the direct,
//     indirect and G-buffer AOVs are GL's within float rounding but at a few edge pixels;
//   - after the scene's meshes move (Pipeline::moveScene), the ray caster follows them;
//   - the manifest's compute report says where each pass ran and whether images were uploaded.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "framework/experiment/experiment.h"
#include "framework/experiment/experiment_renderer.h"
#include "framework/pipeline/pipeline.h"
#include "gl/gl_test_context.h"

namespace lpvlab {
namespace {

struct Frame {
  std::vector<NamedImage> aovs;
  nlohmann::json compute;
};

// Two frames of the default experiment (small), the second after the first mesh moved up 5 cm.
std::pair<Frame, Frame> frames(const std::string& raster, const std::string& backend) {
  test::glTestContext();
  Experiment e = loadExperiment("", {"output.width=96", "output.height=72",
                                     "light_maps.rsm_resolution=32", "light_maps.shadow_resolution=256",
                                     "grid.resolution=8", "propagation.iterations=4",
                                     "compute.raster=\"" + raster + "\"", "compute.backend=\"" + backend + "\""});
  ShaderCompiler shaders;
  RasterPlan plan = chooseExperimentRaster(e);
  Scene scene = e.scene;
  Pipeline pipeline(scene, e.camera, e.settings, std::move(e.method), shaders, std::move(plan));
  pipeline.renderFrame();
  Frame first{pipeline.readOutputs(), pipeline.computeReport()};
  for (glm::vec3& p : scene.meshes.front().positions) p.y += 0.05f;
  pipeline.moveScene(scene, false, true);
  pipeline.renderFrame();
  return {std::move(first), Frame{pipeline.readOutputs(), pipeline.computeReport()}};
}

// Equal within float rounding but at the few pixels a triangle edge or a shadow map's edge
// crosses (which side covers a pixel centre on an edge is the rasteriser's tie-break): at most
// 0.2% of the values differ by more than 1e-3 of the image's largest, and the means agree.
void expectSameAovs(const Frame& rays, const Frame& gl, const std::string& what) {
  for (const char* name : {"direct", "indirect", "albedo", "normal", "depth"}) {
    const Image& a = findAov(rays.aovs, name);
    const Image& b = findAov(gl.aovs, name);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    double scale = 0.0, sumA = 0.0, sumB = 0.0;
    for (float v : b.pixels) scale = std::max(scale, double(std::abs(v)));
    std::size_t differing = 0;
    for (std::size_t i = 0; i < b.pixels.size(); ++i) {
      differing += std::abs(a.pixels[i] - b.pixels[i]) > 1e-3 * scale ? 1 : 0;
      sumA += a.pixels[i];
      sumB += b.pixels[i];
    }
    EXPECT_GT(scale, 0.0) << what << ", " << name << ": all black";
    EXPECT_LE(double(differing), 0.002 * double(b.pixels.size())) << what << ", " << name;
    EXPECT_NEAR(sumA, sumB, 0.005 * std::abs(sumB)) << what << ", " << name;
  }
}

TEST(RasterPipeline, RayCastFramesAreGlsOnEitherBackendAndFollowMovedMeshes) {
  for (const std::string backend : {"cpu", "gl"}) {
    const auto [glFirst, glMoved] = frames("gl", backend);
    const auto [raysFirst, raysMoved] = frames("embree", backend);
    expectSameAovs(raysFirst, glFirst, backend + " backend");
    expectSameAovs(raysMoved, glMoved, backend + " backend, after a move");
    // The move changed the image: the comparison above is not of two unmoved frames.
    const Image& before = findAov(raysFirst.aovs, "depth");
    const Image& after = findAov(raysMoved.aovs, "depth");
    EXPECT_NE(before.pixels, after.pixels);
    const nlohmann::json& raster = raysFirst.compute.at("raster");
    for (const char* pass : {"gbuffer", "rsm", "shadow_maps"}) EXPECT_EQ(raster.at("passes").at(pass), "embree");
    EXPECT_EQ(raster.at("uploaded_to_gl"), backend == "gl") << "GL strategies read the images as textures";
    EXPECT_TRUE(raster.contains("embree"));
    EXPECT_EQ(glFirst.compute.at("raster").at("passes").at("gbuffer"), "gl");
  }
}

}  // namespace
}  // namespace lpvlab
