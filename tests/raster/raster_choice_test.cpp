// [compute] raster and [light_maps] shadows (framework/raster/raster_choice.h): what each choice
// gives, per pass, and what is refused with the key named:
//   - "auto" on llvmpipe weighs each pass by raster_cost.h's model: on the Cornell box (a few
//     dozen triangles) every pass stays on GL; in Sponza (262k triangles, the sun) the G-buffer and
//     the RSM go to the ray caster and the 2048^2 shadow map stays on GL, as measured
//     (docs/benchmarks.md#raster-passes);
//   - "auto" on a GPU, or with the compute backend on GL, keeps every pass on GL;
//   - "embree" puts every pass on the ray caster; "gl" none;
//   - shadow rays make the ray caster whatever the passes, and are refused with direct light on
//     GL; "embree" and shadow rays are refused with light-field particles; an unknown choice is
//     refused.

#include <gtest/gtest.h>

#include <string>

#include "framework/core/error.h"
#include "framework/experiment/experiment.h"
#include "framework/raster/raster_choice.h"
#include "framework/raster/raster_cost.h"

namespace lpvlab {
namespace {

const std::string kLlvmpipe = "llvmpipe (LLVM 15.0.6, 256 bits)";
const std::string kGpu = "NVIDIA H200/PCIe/SSE2";

std::string experimentFile(const std::string& name) {
  return name.empty() ? "" : std::string(LPVLAB_SOURCE_DIR "/experiments/") + name;
}

RasterPlan plan(const Experiment& e, const std::string& renderer, int views = 1, bool lightField = false) {
  return chooseRaster({.glRenderer = renderer, .lightFieldParticles = lightField, .lightViews = views},
                      e.scene, e.settings);
}

std::string refusal(const Experiment& e, const std::string& renderer, bool lightField = false) {
  try {
    plan(e, renderer, 1, lightField);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(RasterChoice, AutoWeighsEachPassOnASoftwareRenderer) {
  const Experiment cornell = loadExperiment("", {});
  const RasterPlan small = plan(cornell, kLlvmpipe, 5);
  EXPECT_TRUE(small.hostPasses.empty()) << small.record.dump();
  EXPECT_FALSE(small.host) << "no pass and no shadow ray needs the ray caster";
  for (const char* pass : {kShadowMapPass, kRsmPass, kGBufferPass}) {
    EXPECT_LT(small.record.at("model_ms").at(pass).at("llvmpipe").get<double>(),
              small.record.at("model_ms").at(pass).at("embree").get<double>());
  }
  const Experiment sponza = loadExperiment(experimentFile("sponza_sun.toml"),
                                           {"output.width=320", "output.height=180"});
  const RasterPlan large = plan(sponza, kLlvmpipe, 1);
  EXPECT_EQ(large.hostPasses, (std::set<std::string>{kGBufferPass, kRsmPass})) << large.record.dump();
  EXPECT_TRUE(large.host);
  EXPECT_GT(large.record.at("model_ms").at(kShadowMapPass).at("embree").get<double>(),
            large.record.at("model_ms").at(kShadowMapPass).at("llvmpipe").get<double>());
}

TEST(RasterChoice, AutoKeepsGlOnAGpuOrWithTheBackendOnGl) {
  const Experiment sponza = loadExperiment(experimentFile("sponza_sun.toml"), {});
  EXPECT_TRUE(plan(sponza, kGpu).hostPasses.empty());
  const Experiment onGl = loadExperiment(experimentFile("sponza_sun.toml"), {"compute.backend=\"gl\""});
  EXPECT_TRUE(plan(onGl, kLlvmpipe).hostPasses.empty());
}

TEST(RasterChoice, EmbreeAndGlAreEveryPass) {
  const Experiment embree = loadExperiment("", {"compute.raster=\"embree\""});
  EXPECT_EQ(plan(embree, kGpu).hostPasses,
            (std::set<std::string>{kGBufferPass, kRsmPass, kShadowMapPass}));
  const Experiment gl = loadExperiment("", {"compute.raster=\"gl\""});
  const RasterPlan none = plan(gl, kLlvmpipe);
  EXPECT_TRUE(none.hostPasses.empty());
  EXPECT_FALSE(none.host);
}

TEST(RasterChoice, ShadowRaysMakeTheRayCasterAndNeedDirectLightOnTheCpu) {
  const Experiment rays = loadExperiment("", {"compute.raster=\"gl\"", "light_maps.shadows=\"rays\""});
  const RasterPlan withRays = plan(rays, kLlvmpipe);
  EXPECT_TRUE(withRays.host);
  EXPECT_TRUE(withRays.hostPasses.empty());
  const std::string onGpu = refusal(rays, kGpu);  // auto backend on a GPU: direct light on GL
  EXPECT_NE(onGpu.find("light_maps.shadows"), std::string::npos) << onGpu;
  EXPECT_NE(onGpu.find("compute] backend"), std::string::npos) << onGpu;
}

TEST(RasterChoice, RefusesWhatTheRayCasterCannotSeeAndUnknownChoices) {
  const Experiment embree = loadExperiment("", {"compute.raster=\"embree\""});
  const std::string particles = refusal(embree, kLlvmpipe, /*lightField=*/true);
  EXPECT_NE(particles.find("compute.raster"), std::string::npos) << particles;
  EXPECT_NE(particles.find("light field"), std::string::npos) << particles;
  const Experiment rays = loadExperiment("", {"light_maps.shadows=\"rays\""});
  EXPECT_NE(refusal(rays, kLlvmpipe, true).find("light_maps.shadows"), std::string::npos);
  // "auto" with light-field particles quietly keeps GL (their billboards are GL programs).
  const Experiment automatic = loadExperiment(experimentFile("sponza_sun.toml"), {});
  EXPECT_TRUE(plan(automatic, kLlvmpipe, 1, true).hostPasses.empty());
  Experiment unknown = loadExperiment("", {});
  unknown.settings.raster = "vulkan";
  const std::string bad = refusal(unknown, kLlvmpipe);
  EXPECT_NE(bad.find("compute.raster"), std::string::npos) << bad;
  EXPECT_THROW(loadExperiment("", {"compute.raster=\"vulkan\""}), Error);
  EXPECT_THROW(loadExperiment("", {"light_maps.shadows=\"pcss\""}), Error);
}

// The model's two sides grow as raster_cost.h says: ray casting with texels alone, llvmpipe with
// the triangles drawn per view.
TEST(RasterChoice, TheCostModelGrowsWithTexelsAndTriangles) {
  const RasterPassCost few = estimateRasterPass({.texels = 1e6, .views = 1, .triangles = 100});
  const RasterPassCost many = estimateRasterPass({.texels = 1e6, .views = 1, .triangles = 1e6});
  EXPECT_DOUBLE_EQ(few.raysMs, many.raysMs);
  EXPECT_GT(many.llvmpipeMs, few.llvmpipeMs);
  EXPECT_FALSE(few.raysFaster());
  EXPECT_TRUE(many.raysFaster());
  const RasterPassCost depth = estimateRasterPass({.texels = 1e6, .views = 1, .triangles = 100, .colour = false});
  EXPECT_LT(depth.raysMs, few.raysMs);
}

}  // namespace
}  // namespace lpvlab
