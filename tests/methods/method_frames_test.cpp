// Every indirect method through the pipeline's life: an animation's move renders what a fresh
// pipeline on the moved scene renders, extreme inputs stay finite, and the run's reports (stages,
// work, memory) have the same shape as LPV's.

#include <cmath>

#include "framework/pipeline/raster_inputs.h"
#include "method_test_support.h"

namespace lpvlab {
namespace {

const std::vector<std::vector<std::string>> kMethods = {
    {"indirect.method=instant_radiosity", "indirect.light_paths=64"},
    {"indirect.method=instant_radiosity", "indirect.light_paths=64", "indirect.visibility=none",
     "indirect.clamp=5"},
    {"indirect.method=rsm_gather", "indirect.samples=32", "light_maps.rsm_resolution=32"},
    {"indirect.method=rsm_gather", "indirect.pattern=all", "light_maps.rsm_resolution=16"},
    {"indirect.method=instant_radiosity", "indirect.light_paths=32",
     "indirect.visibility=\"shadow_maps\"", "indirect.shadow_map_size=16"},
    {"indirect.method=imperfect_shadow_maps", "indirect.light_paths=32", "indirect.points_per_vpl=256"},
    {"indirect.method=radiosity", "indirect.patch_size=0.25", "indirect.form_factors=rays", "indirect.rays=64"},
    {"indirect.method=radiosity", "indirect.patch_size=0.5", "indirect.hemicube_resolution=16",
     "indirect.solver=shooting", "indirect.adaptive_levels=1"}};
// Incremental instant radiosity keeps its VPLs between frames: a moved light gives it a set that
// differs from a fresh one (its own tests: incremental_instant_radiosity_test.cpp).
const std::vector<std::vector<std::string>> kKeepingMethods = {
    {"indirect.method=incremental_instant_radiosity", "indirect.vpls=32"}};

std::vector<std::vector<std::string>> allMethods() {
  std::vector<std::vector<std::string>> all = kMethods;
  all.insert(all.end(), kKeepingMethods.begin(), kKeepingMethods.end());
  return all;
}

std::vector<std::string> small(std::vector<std::string> overrides) {
  overrides.push_back("output.width=40");
  overrides.push_back("output.height=32");
  return overrides;
}

std::string label(const std::vector<std::string>& overrides) {
  std::string out;
  for (const std::string& o : overrides) out += o + " ";
  return out;
}

// The plates scene with its light and cube moved.
Scene moved(Scene scene, bool light, bool geometry) {
  if (light) scene.lights[0].position = glm::vec3(-0.4f, 0.8f, -0.3f);
  if (geometry)
    for (std::size_t m = 2; m < scene.meshes.size(); ++m)
      for (glm::vec3& p : scene.meshes[m].positions) p += glm::vec3(0.2f, 0.05f, 0.0f);
  return scene;
}

TEST(MethodFrames, AMovedSceneRendersAsAFreshPipelineOnIt) {
  test::glTestContext();
  const Scene scene = test::platesScene();
  const Camera camera = test::platesCamera();
  for (const auto& overrides : kMethods)
    for (const auto& [light, geometry] : {std::pair{true, false}, std::pair{false, true}}) {
      SCOPED_TRACE(label(overrides) + (light ? "light moved" : "geometry moved"));
      Experiment e = loadExperiment("", small(overrides));
      ShaderCompiler shaders;
      Pipeline pipeline(scene, camera, e.settings, std::move(e.method), shaders);
      pipeline.renderFrame();
      const Image before = findAov(pipeline.readOutputs(), "indirect");
      const Scene next = moved(scene, light, geometry);
      pipeline.moveScene(next, light, geometry);
      pipeline.renderFrame();
      const Image after = findAov(pipeline.readOutputs(), "indirect");
      const test::MethodRun fresh = test::runMethod(small(overrides), &next, &camera);
      EXPECT_NE(after.pixels, before.pixels);
      // Bit for bit: the same VPLs (same seed) and the same G-buffer.
      EXPECT_EQ(after.pixels, fresh.indirect().pixels);
    }
}

TEST(MethodFrames, ExtremeLightsAndEmptyVplSetsStayFinite) {
  const Camera camera = test::platesCamera();
  for (const auto& overrides : allMethods())
    for (const float intensity : {0.0f, 1e-12f, 1e12f}) {
      SCOPED_TRACE(label(overrides) + "intensity " + std::to_string(intensity));
      Scene scene = test::platesScene();
      scene.lights[0].intensity = intensity;
      const test::MethodRun run = test::runMethod(small(overrides), &scene, &camera);
      double sum = 0.0;
      for (float v : run.indirect().pixels) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
        sum += v;
      }
      if (intensity > 0.0f) {
        EXPECT_GT(sum, 0.0);  // even 1e-12 W/sr leaves a trace in float
      } else {
        EXPECT_EQ(sum, 0.0);  // a dark light: no VPL, no light, no error
      }
    }
  // A spot light aimed away from every surface: no VPL, no light, no NaN.
  for (const auto& overrides : allMethods()) {
    SCOPED_TRACE(label(overrides) + "spot into the void");
    Scene scene = test::platesScene();
    scene.lights[0] = Light{.name = "away", .type = LightType::Spot,
                            .position = glm::vec3(0.0f, 0.5f, 1.5f), .direction = glm::vec3(0, 0, 1),
                            .intensity = 10.0f, .outerConeAngle = 0.3f};
    const test::MethodRun run = test::runMethod(small(overrides), &scene, &camera);
    for (float v : run.indirect().pixels) ASSERT_EQ(v, 0.0f);
    if (run.statistics.contains("vpls")) {
      EXPECT_EQ(run.statistics["vpls"].get<int>(), 0);
    }
  }
}

TEST(MethodFrames, ReportsHaveLpvsShapeWithTheMethodsStages) {
  test::glTestContext();
  for (const auto& overrides : allMethods()) {
    SCOPED_TRACE(label(overrides));
    Experiment e = loadExperiment("", small(overrides));
    ShaderCompiler shaders;
    Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
    const FrameTimes times = pipeline.renderFrame();
    const IndirectMethod& method = pipeline.method();
    for (const std::string& stage : method.stageNames()) {
      EXPECT_TRUE(times.stageMs.count(stage)) << stage;
      EXPECT_TRUE(times.wallMs.count(stage)) << stage;
    }
    for (const char* stage : {"clear", "occlusion", "injection", "propagation"})
      EXPECT_FALSE(times.stageMs.count(stage)) << stage;
    // Only a method that reads the RSMs has them rendered.
    const bool readsRsm = method.consumes().count(std::string(raster::kReflectiveShadowMaps.name)) > 0;
    EXPECT_EQ(times.stageMs.count("rsm"), readsRsm ? 1u : 0u);
    EXPECT_EQ(readsRsm, method.name() == "rsm_gather");
    const nlohmann::json work = pipeline.workReport();
    for (const std::string& stage : method.stageNames()) {
      ASSERT_TRUE(work.contains(stage)) << stage;
      double units = 0.0;
      for (const auto& entry : work[stage]) units += entry["units"].get<double>();
      EXPECT_GT(units, 0.0) << stage;
    }
    const nlohmann::json memory = pipeline.memoryReport();
    EXPECT_GT(memory["indirect_method"].get<double>(), 0.0);
    EXPECT_FALSE(memory.contains("light_grid"));  // no grid is allocated
    EXPECT_EQ(pipeline.computeReport()["indirect_method"]["name"], method.name());
    EXPECT_FALSE(pipeline.derivativeRefusal("indirect.clamp").empty());
  }
}

}  // namespace
}  // namespace lpvlab
