// Incremental instant radiosity (variants/methods/incremental_instant_radiosity and
// framework/many_lights/incremental_vpls.h): a still light's frames equal to a fresh set's, and
// after a light moves only valid VPLs, spread within a stated bound (its triangulation's own
// tests: tests/many_lights/disk_triangulation_test.cpp).

#include <cmath>
#include <iostream>

#include "framework/many_lights/incremental_vpls.h"
#include "framework/many_lights/ray_scene.h"
#include "method_test_support.h"

namespace lpvlab {
namespace {

std::vector<std::string> iir(std::vector<std::string> more = {}) {
  std::vector<std::string> out = {"output.width=48", "output.height=36",
                                  "indirect.method=incremental_instant_radiosity", "indirect.vpls=96"};
  out.insert(out.end(), more.begin(), more.end());
  return out;
}

// On the plates scene (a point light: two charts) and in the Cornell box (a spot whose rays out of
// the open front leave placeholders, and whose rim VPLs must not drift out of the chart).
TEST(IncrementalInstantRadiosity, AStillLightKeepsItsVplsAndImageAndMatchesAFreshSet) {
  test::glTestContext();
  for (const bool plates : {true, false}) {
    SCOPED_TRACE(plates ? "plates" : "Cornell box");
    Experiment e = loadExperiment("", iir());
    const Scene scene = plates ? test::platesScene() : e.scene;
    const Camera camera = plates ? test::platesCamera() : e.camera;
    ShaderCompiler shaders;
    Pipeline pipeline(scene, camera, e.settings, std::move(e.method), shaders);
    pipeline.renderFrame();
    const Image first = findAov(pipeline.readOutputs(), "indirect");
    const nlohmann::json filled = pipeline.method().statistics();
    EXPECT_EQ(filled["inserted"].get<int>(), filled["kept"].get<int>());
    for (int frame = 1; frame < 4; ++frame) {
      pipeline.renderFrame();
      const nlohmann::json s = pipeline.method().statistics();
      EXPECT_EQ(s["inserted"].get<int>(), 0) << frame;
      EXPECT_EQ(s["removed_invalid"].get<int>() + s["removed_dense"].get<int>(), 0) << frame;
      EXPECT_EQ(findAov(pipeline.readOutputs(), "indirect").pixels, first.pixels) << frame;
    }
    const test::MethodRun fresh = test::runMethod(iir(), &scene, &camera);
    EXPECT_EQ(fresh.indirect().pixels, first.pixels);
    std::cout << (plates ? "plates" : "Cornell box") << ", a still light: " << filled["kept"]
              << " VPLs (" << filled["placeholders"] << " placeholders for light lost through "
              << "open sides), coverage " << filled["coverage"] << "\n";
    EXPECT_GT(filled["placeholders"].get<int>(), 0);
    EXPECT_LT(filled["coverage"].get<double>(), 1.7);
  }
}

// The plates scene's light moves in steps; after each frame every kept VPL is valid for the moved
// light, and once the limits have caught up the coverage is back within its bound.
TEST(IncrementalInstantRadiosity, AfterALightMovesEveryKeptVplIsValidAndCoverageRecovers) {
  Scene scene = test::platesScene();
  // A spot aimed down at the floor, so its chart's rim is the cone and the cube's shadow moves.
  scene.lights[0] = Light{.name = "spot", .type = LightType::Spot, .position = glm::vec3(0.5f, 0.95f, 0.3f),
                          .direction = glm::vec3(0, -1, 0), .intensity = 3.0f,
                          .innerConeAngle = 0.4f, .outerConeAngle = 1.2f};
  RayScene rays(scene);
  IncrementalSettings settings;
  settings.vpls = 128;
  settings.maxRemovals = 12;
  settings.maxInsertions = 12;
  IncrementalVpls set(settings);
  IncrementalCounts counts;
  set.update(rays, counts);
  const double initial = counts.coverage;
  int removedInvalid = 0, frames = 0;
  for (int step = 1; step <= 6; ++step) {
    scene.lights[0].position = glm::vec3(0.5f - 0.15f * step, 0.95f, 0.3f - 0.08f * step);
    rays.moveLights(scene);
    rays.update();
    set.update(rays, counts);
    ++frames;
    removedInvalid += counts.removedInvalid;
    for (const Vpl& vpl : set.vpls()) ASSERT_TRUE(set.valid(rays, vpl)) << "frame " << step;
    EXPECT_LE(counts.inserted, settings.maxInsertions);
    EXPECT_LE(counts.removedDense, settings.maxRemovals);
  }
  // The light stops; the limits catch up within a few frames.
  for (int more = 0; more < 20 && (counts.inserted > 0 || counts.removedDense > 0); ++more) {
    set.update(rays, counts);
    ++frames;
    for (const Vpl& vpl : set.vpls()) ASSERT_TRUE(set.valid(rays, vpl));
  }
  std::cout << "coverage " << initial << " filled, " << counts.coverage << " after the light moved ("
            << removedInvalid << " VPLs invalidated over 6 moves, " << frames << " frames), "
            << counts.kept << " kept\n";
  EXPECT_GT(removedInvalid, 0);
  EXPECT_EQ(counts.inserted, 0);
  EXPECT_EQ(counts.kept, settings.vpls);
  EXPECT_LT(counts.coverage, 2.0);  // the stated bound: at most twice a packing's sqrt(1/n)
}

}  // namespace
}  // namespace lpvlab
