// Direct light on the CPU backend (framework/pipeline/direct_lighting_cpu.h), which calls the GL
// kernel's per-pixel function (shaders/lighting/direct_light.glsl) and writes out GL's 2x2
// depth-compare filter (shaders/lighting/shadow_tap.glsl) where GL asks its texture unit:
//   a. for a spot light (the Cornell box), a point light (Sibenik's lamp, six cube faces) and a
//      directional light (Sponza's sun, an orthographic view) it gives GL's image within float
//      rounding, but for rare shadow comparisons (backend_comparison.h), whose share it prints;
//   b. the image does not depend on the thread count, bit for bit.
// (Against an independent method: reference_agreement_test.cpp compares the default backend's
// direct light, the CPU's here, with the path tracer's.)

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <iostream>
#include <string>
#include <vector>

#include "backend_comparison.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "framework/reference/camera_rays.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

// The direct light of an experiment (a small frame) on `backend`; with `emission`, every material
// of its scene emits that radiance.
// `more`: further overrides. `depth`: if given, receives the frame's depth AOV.
Image directLight(const std::string& file, const std::string& backend,
                  const glm::vec3& emission = glm::vec3(0.0f),
                  const std::vector<std::string>& more = {}, Image* depth = nullptr) {
  test::glTestContext();
  std::vector<std::string> overrides = {"output.width=160",
                                        "output.height=120",
                                        "light_maps.shadow_resolution=256",
                                        "light_maps.rsm_resolution=32",
                                        "grid.resolution=8",
                                        "propagation.iterations=1",
                                        "compute.backend=" + backend};
  overrides.insert(overrides.end(), more.begin(), more.end());
  Experiment e = loadExperiment(file, overrides);
  for (Material& m : e.scene.materials) m.emission = emission;
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  EXPECT_EQ(pipeline.computeReport().at("direct"), backend);
  pipeline.renderFrame();
  const std::vector<NamedImage> outputs = pipeline.readOutputs();
  if (depth) *depth = findAov(outputs, "depth");
  return findAov(outputs, "direct");
}

std::string experiment(const std::string& name) {
  return name.empty() ? "" : std::string(LPVLAB_SOURCE_DIR) + "/experiments/" + name;
}

TEST(DirectLighting, CpuGivesGlsImageForSpotPointAndDirectionalLights) {
  for (const std::string name : {"", "sibenik_lamp.toml", "sponza_sun.toml"}) {
    const Image cpu = directLight(experiment(name), "cpu");
    const Image gl = directLight(experiment(name), "gl");
    const std::string what = name.empty() ? "cornell box (spot)" : name;
    test::expectSameDirectLight(cpu, gl, what);
    const test::ImageDifference d = test::difference(cpu, gl);
    std::cout << "[ direct ] " << what << ": " << 100.0 * d.differing
              << "% of values off by more than 1e-4 of the largest (shadow comparisons), "
              << "largest difference " << d.largest / d.scale << " of the largest value\n";
  }
}

// Sponza's sun with its view an 8 m box following the camera (light_views.h): the shadow map
// knows nothing outside the box, so what the camera sees there gets no direct light, and inside it
// the sunlit floor and walls do; the same on both backends.
TEST(DirectLighting, ASunViewFollowingTheCameraLightsOnlyItsBoxOnBothBackends) {
  const std::vector<std::string> follow = {"light_maps.directional=\"camera\"",
                                           "light_maps.directional_width=8.0"};
  Image depth;
  const Image cpu =
      directLight(experiment("sponza_sun.toml"), "cpu", glm::vec3(0.0f), follow, &depth);
  const Image gl = directLight(experiment("sponza_sun.toml"), "gl", glm::vec3(0.0f), follow);
  test::expectSameDirectLight(cpu, gl, "sponza_sun.toml, the sun's view following the camera");

  const Experiment e = loadExperiment(experiment("sponza_sun.toml"), follow);
  const GpuView view =
      buildLightViews(e.scene.lights, e.scene.bounds(), directionalFollow(e.settings, e.camera))
          .views.at(0);
  const CameraRays rays(e.camera, cpu.width, cpu.height);
  // Margins of two shadow texels (the lookup moves 1.5 texels along the normal; the taps reach
  // 1.5 more) and of the box's own edge.
  const float margin = 2.0f * 2.0f / 256.0f;
  int outside = 0, inside = 0, litInside = 0;
  for (int y = 0; y < cpu.height; ++y)
    for (int x = 0; x < cpu.width; ++x) {
      const float d = depth.at(x, y, 0);
      if (d <= 0.0f) continue;
      const glm::vec4 clip =
          view.clipFromWorld *
          glm::vec4(rays.surfacePoint(float(x) + 0.5f, float(y) + 0.5f, d), 1.0f);
      const float reach = std::max(std::abs(clip.x), std::abs(clip.y));
      const float light = cpu.at(x, y, 0) + cpu.at(x, y, 1) + cpu.at(x, y, 2);
      if (reach > 1.0f + 2.0f * margin) {
        ++outside;
        EXPECT_EQ(light, 0.0f) << "pixel " << x << ", " << y << " is outside the box";
      } else if (reach < 1.0f - 2.0f * margin) {
        ++inside;
        litInside += light > 0.0f;
      }
    }
  EXPECT_GT(outside, cpu.width * cpu.height / 10) << "the box leaves part of the view out";
  EXPECT_GT(inside, cpu.width * cpu.height / 10);
  EXPECT_GT(litInside, inside / 10) << "the sun lights the floor and walls inside the box";
  std::cout << "[ direct ] sun view following the camera: " << outside
            << " pixels outside its box (unlit), " << litInside << " of " << inside
            << " inside it lit\n";
}

// A scene without emitters never renders the G-buffer's emission image (direct light reads zeros);
// with one, each surface's direct light is its emission more, on both backends.
TEST(DirectLighting, EmissionAddsExactlyTheEmittedRadianceOnBothBackends) {
  const glm::vec3 emission(0.25f, 0.5f, 2.0f);
  for (const std::string backend : {"cpu", "gl"}) {
    const Image plain = directLight("", backend), emitting = directLight("", backend, emission);
    ASSERT_EQ(plain.pixels.size(), emitting.pixels.size());
    int surfaces = 0;
    for (int y = 0; y < plain.height; ++y)
      for (int x = 0; x < plain.width; ++x) {
        // The box fills the frame but for its open front's edges: a pixel without a surface is
        // black in both.
        const bool lit = emitting.at(x, y, 0) > 0.0f;
        surfaces += lit ? 1 : 0;
        for (int c = 0; c < 3; ++c) {
          const float expected = lit ? plain.at(x, y, c) + emission[c] : 0.0f;
          EXPECT_NEAR(emitting.at(x, y, c), expected, 1e-5f * (1.0f + expected))
              << backend << " pixel " << x << ", " << y;
        }
      }
    EXPECT_GT(surfaces, plain.width * plain.height / 2) << backend;
  }
}

TEST(DirectLighting, CpuImageDoesNotDependOnTheThreadCount) {
  const Image two = directLight("", "cpu");
  Image one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = directLight("", "cpu");
  }
  EXPECT_EQ(one.pixels, two.pixels);
}

}  // namespace
}  // namespace lpvlab
