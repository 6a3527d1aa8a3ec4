// The shadow-map pass draws surfaces without alpha masks through a fragment-free program and the
// alpha-masked ones through the material's alpha test (framework/pipeline/raster_passes.cpp).
// Both must cast their shadows: a plane under a tilted sun, with an opaque square and a half
// cut-out, alpha-masked square 1 m above it. The plane's direct light is albedo / pi * E cos(theta)
// where the way to the sun is open or passes the cut-out half, and 0 where it meets the opaque
// square or the kept half of the masked one (up to the shadow map's own acne at this angle). Pixels are classified by the world position they
// see (from the depth AOV) and where the sunward ray from there crosses the squares' height,
// with a margin around every edge. Exact shadow rays ([light_maps] shadows = "rays") meet the
// same classification with no acne and a margin of a pixel.

#include <cmath>

#include <gtest/gtest.h>

#include "framework/experiment/experiment.h"
#include "framework/experiment/experiment_renderer.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/pipeline/pipeline.h"
#include "pipeline_test_support.h"
#include "reference/test_scenes.h"

namespace lpvlab {
namespace {

constexpr float kPlaneAlbedo = 0.5f;
constexpr float kIrradiance = 2.0f;
const glm::vec3 kSun = glm::normalize(glm::vec3(-1.5f, -1.0f, 0.0f));  // the light's direction

Scene shadowScene() {
  Scene scene;
  scene.source = "test:shadow pass";
  TextureImage texture{.path = "test:left half cut out", .width = 4, .height = 1};
  for (std::uint8_t alpha : {0, 0, 255, 255})
    texture.rgba8.insert(texture.rgba8.end(), {255, 255, 255, alpha});
  scene.textures = {texture};
  scene.materials = {{.name = "grey", .baseColor = glm::vec3(kPlaneAlbedo)},
                     {.name = "leaf", .baseColor = glm::vec3(1.0f), .baseColorTexture = 0,
                      .alphaMode = AlphaMode::Mask, .alphaCutoff = 0.5f}};
  // The masked square spans x in [-1, 1] (u = (x + 1) / 2: cut out for x < 0); the opaque one
  // x in [2, 4]; both z in [-1, 1], 1 m above the plane.
  scene.meshes = {testing::horizontalSquare("plane", 0, 6.0f, 0.0f),
                  testing::horizontalSquare("leaf", 1, 1.0f, 1.0f),
                  testing::quad("blocker", 0, {glm::vec3(2, 1, 1), glm::vec3(4, 1, 1),
                                               glm::vec3(4, 1, -1), glm::vec3(2, 1, -1)})};
  scene.lights = {{.name = "sun", .type = LightType::Directional, .direction = kSun,
                   .intensity = kIrradiance}};
  scene.cameras = {testing::lookingDown({1.0f, 6.0f, 0.0f}, glm::radians(70.0f))};
  return scene;
}

// How closely a shadowing method must match the classification: `margin` metres around every
// edge are left out, lit pixels within `litTolerance` x the lit value, shadowed ones below
// `darkTolerance` x it.
struct ShadowBounds {
  double margin, litTolerance, darkTolerance;
};

void expectShadows(Pipeline& pipeline, const Camera& camera, const ShadowBounds& bounds) {
  pipeline.renderFrame();
  const std::vector<NamedImage> aovs = pipeline.readOutputs();
  const Image& direct = findAov(aovs, "direct");
  const Image& depth = findAov(aovs, "depth");

  const double lit = kPlaneAlbedo / M_PI * kIrradiance * -kSun.y;
  int open = 0, throughHole = 0, underLeaf = 0, underBlocker = 0;
  const auto near = [&](double v, double edge) { return std::abs(v - edge) < bounds.margin; };
  for (int y = 0; y < direct.height; ++y)
    for (int x = 0; x < direct.width; ++x) {
      const glm::dvec3 p = glm::dvec3(camera.position) +
                           double(depth.at(x, y, 0)) *
                               test::cameraRay(camera, direct.width, direct.height, x, y);
      if (depth.at(x, y, 0) <= 0.0f || std::abs(p.y) > 0.01) continue;  // not the plane
      // Where the way to the sun crosses y = 1.
      const glm::dvec3 q = p + glm::dvec3(-kSun) / double(-kSun.y);
      if (near(std::abs(q.z), 1.0) || near(q.x, -1.0) || near(q.x, 0.0) || near(q.x, 1.0) ||
          near(q.x, 2.0) || near(q.x, 4.0))
        continue;  // an edge: the shadow map's texels and the mask's filtering decide
      const bool inZ = std::abs(q.z) < 1.0;
      double expected = lit;
      if (inZ && q.x > -1.0 && q.x < 0.0) ++throughHole;
      else if (inZ && q.x > 0.0 && q.x < 1.0) expected = 0.0, ++underLeaf;
      else if (inZ && q.x > 2.0 && q.x < 4.0) expected = 0.0, ++underBlocker;
      else ++open;
      if (expected > 0.0)
        ASSERT_NEAR(direct.at(x, y, 0), expected, bounds.litTolerance * lit)
            << "pixel " << x << ", " << y << " at x " << p.x << ", z " << p.z;
      else
        ASSERT_LT(direct.at(x, y, 0), bounds.darkTolerance * lit)
            << "pixel " << x << ", " << y << " at x " << p.x << ", z " << p.z;
    }
  EXPECT_GT(open, 20);
  EXPECT_GT(throughHole, 4);
  EXPECT_GT(underLeaf, 4);
  EXPECT_GT(underBlocker, 4);
}

TEST(ShadowPass, OpaqueAndAlphaMaskedSurfacesBothCastShadows) {
  test::glTestContext();
  Experiment e = loadExperiment("", {"output.width=128", "output.height=128"});
  const Scene scene = shadowScene();
  const Camera& camera = scene.cameras.front();
  ShaderCompiler shaders;
  Pipeline pipeline(scene, camera, e.settings, std::move(e.method), shaders);
  // Lit or shadowed is what this test decides; the exact lit value at this grazing sun also
  // depends on the shadow map's bias and filtering (a few % of acne), so: within 10%.
  expectShadows(pipeline, camera, {.margin = 0.2, .litTolerance = 0.1, .darkTolerance = 0.02});
}

// [light_maps] shadows = "rays" (framework/raster/ray_raster.h's shadow rays): the same
// classification, exact up to a pixel's footprint (5 cm here, against the maps' 20 cm): lit
// pixels get the closed form within float rounding, shadowed ones nothing at all. No shadow map
// is rendered.
TEST(ShadowPass, ShadowRaysAreExact) {
  test::glTestContext();
  Experiment e = loadExperiment("", {"output.width=128", "output.height=128",
                                     "light_maps.shadows=\"rays\"", "compute.backend=\"cpu\""});
  e.scene = shadowScene();
  e.camera = e.scene.cameras.front();
  ShaderCompiler shaders;
  RasterPlan plan = chooseExperimentRaster(e);
  ASSERT_TRUE(plan.host) << "shadow rays need the ray caster";
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders, std::move(plan));
  EXPECT_FALSE(pipeline.renders(raster::kShadowMaps.name));
  EXPECT_EQ(pipeline.computeReport().at("shadows"), "rays");
  expectShadows(pipeline, e.camera, {.margin = 0.05, .litTolerance = 1e-4, .darkTolerance = 1e-6});
}

}  // namespace
}  // namespace lpvlab
