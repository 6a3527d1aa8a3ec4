// Direct light on the CPU backend (framework/pipeline/direct_lighting_cpu.h), which calls the GL
// kernel's per-pixel function (shaders/lighting/direct_light.glsl) and writes out GL's 2x2
// depth-compare filter (shaders/lighting/shadow_tap.glsl) where GL asks its texture unit:
//   a. for a spot light (the Cornell box), a point light (Sibenik's lamp, six cube faces) and a
//      directional light (Sponza's sun, an orthographic view) it gives GL's image within float
//      rounding, but for rare shadow comparisons (backend_comparison.h), whose share it prints;
//   b. the image does not depend on the thread count, bit for bit.
// (Against an independent method: reference_agreement_test.cpp compares the default backend's
// direct light, the CPU's here, with the path tracer's.)

#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "backend_comparison.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

// The direct light of an experiment (a small frame) on `backend`; with `emission`, every material
// of its scene emits that radiance.
Image directLight(const std::string& file, const std::string& backend,
                  const glm::vec3& emission = glm::vec3(0.0f)) {
  test::glTestContext();
  Experiment e = loadExperiment(file, {"output.width=160", "output.height=120",
                                       "light_maps.shadow_resolution=256",
                                       "light_maps.rsm_resolution=32", "grid.resolution=8",
                                       "propagation.iterations=1", "compute.backend=" + backend});
  for (Material& m : e.scene.materials) m.emission = emission;
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.strategies), shaders);
  EXPECT_EQ(pipeline.computeReport().at("direct"), backend);
  pipeline.renderFrame();
  return findAov(pipeline.readOutputs(), "direct");
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
