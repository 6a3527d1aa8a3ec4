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

Image directLight(const std::string& file, const std::string& backend) {
  test::glTestContext();
  Experiment e = loadExperiment(file, {"output.width=160", "output.height=120",
                                       "light_maps.shadow_resolution=256",
                                       "light_maps.rsm_resolution=32", "grid.resolution=8",
                                       "propagation.iterations=1", "compute.backend=" + backend});
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
