// Whole frames at the extremes a study can reach, on both compute backends: grids of 3^3 and
// 256^3 cells, 0 and 1000 iterations, lights of 1e-30 and of the largest intensity an experiment
// allows (1e12), RSMs of one texel, a one-pixel output, and every propagation at SH orders 1-3.
// Each frame must be finite everywhere and keep the injection's flux balance (the grid holds
// the flux the RSM texels reflect); across intensities it must scale exactly (the pipeline is
// linear in the light), so a tiny light neither flushes to zero nor a huge one overflows.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "lpv_support.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

constexpr float kLargestIntensity = 1e12f;  // experiment.cpp's maximum of lights.intensity

struct Frame {
  std::map<std::string, Image> outputs;
  InjectionBalance balance;
};

Frame render(const std::vector<std::string>& overrides, float intensity = -1.0f) {
  test::glTestContext();
  Experiment e = loadExperiment("", overrides);
  if (intensity >= 0.0f)
    for (Light& light : e.scene.lights) light.intensity = intensity;
  static ShaderCompiler shaders;  // compiled kernels are kept across the matrix
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  Frame frame;
  for (NamedImage& aov : pipeline.readOutputs()) frame.outputs[aov.name] = std::move(aov.image);
  frame.balance = test::lpvOf(pipeline).measureInjection();
  return frame;
}

double sum(const Image& image) {
  double s = 0.0;
  for (float v : image.pixels) s += v;
  return s;
}

void expectSound(const Frame& frame, const std::string& what) {
  for (const auto& [name, image] : frame.outputs)
    for (float v : image.pixels) ASSERT_TRUE(std::isfinite(v)) << what << ": " << name;
  ASSERT_GT(frame.balance.rsmFlux, 0.0) << what;
  EXPECT_NEAR(frame.balance.gridFlux / frame.balance.rsmFlux, 1.0, 1e-3) << what;
}

std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

const std::vector<std::string> kSmall = {"output.width=24",   "output.height=24",
                                         "timing.warmup=0",   "light_maps.rsm_resolution=32",
                                         "grid.resolution=8", "propagation.iterations=8"};

struct Composition {
  std::string name;
  std::vector<std::string> overrides;
};

const std::vector<Composition> kPropagations = {
    {"standard_gather", {"propagation.type=standard", "propagation.method=gather"}},
    {"standard_scatter", {"propagation.type=standard", "propagation.method=scatter"}},
    {"standard_gv_bounces",
     {"propagation.type=standard", "occlusion.type=geometry_volume", "propagation.bounces=true"}},
    {"directed", {"propagation.type=directed"}},
    {"tetrahedral", {"propagation.type=tetrahedral"}},
};

class ExtremeMatrix : public ::testing::TestWithParam<std::string> {
 protected:
  std::vector<std::string> onBackend(const std::vector<std::string>& overrides) const {
    return with(overrides, {"compute.backend=" + GetParam()});
  }
};

TEST_P(ExtremeMatrix, EveryPropagationAtEveryOrderScalesFromTheDimmestToTheBrightestLight) {
  for (const Composition& c : kPropagations) {
    for (int order = 1; order <= 3; ++order) {
      const std::string what = c.name + " order " + std::to_string(order) + " on " + GetParam();
      const std::vector<std::string> overrides =
          onBackend(with(with(kSmall, c.overrides), {"grid.sh_order=" + std::to_string(order)}));
      const Frame unit = render(overrides, 1.0f);
      expectSound(unit, what);
      const double unitIndirect = sum(unit.outputs.at("indirect"));
      ASSERT_GT(unitIndirect, 0.0) << what;
      for (float intensity : {1e-30f, kLargestIntensity}) {
        const std::string at = what + " at intensity " + std::to_string(intensity);
        const Frame frame = render(overrides, intensity);
        expectSound(frame, at);
        for (const char* name : {"direct", "indirect"}) {
          const Image& a = unit.outputs.at(name);
          const Image& b = frame.outputs.at(name);
          double worst = 0.0, peak = 0.0;
          for (float v : a.pixels) peak = std::max(peak, double(v));
          for (std::size_t i = 0; i < a.pixels.size(); ++i)
            if (a.pixels[i] > 1e-4 * peak)
              worst = std::max(
                  worst, std::abs(double(b.pixels[i]) / (double(intensity) * a.pixels[i]) - 1.0));
          EXPECT_NEAR(sum(b) / (double(intensity) * sum(a)), 1.0, 1e-4) << at << ": " << name;
          EXPECT_LT(worst, 1e-3) << at << ": " << name;
        }
      }
    }
  }
}

TEST_P(ExtremeMatrix, TheSmallestAndLargestGrids) {
  for (int resolution : {3, 256}) {
    const std::string what = std::to_string(resolution) + "^3 cells on " + GetParam();
    const Frame frame = render(onBackend(with(
        kSmall, {"grid.resolution=" + std::to_string(resolution), "propagation.iterations=2"})));
    expectSound(frame, what);
    EXPECT_GT(sum(frame.outputs.at("indirect")), 0.0) << what;
  }
}

TEST_P(ExtremeMatrix, ZeroAndAThousandIterations) {
  for (int iterations : {0, 1000}) {
    const std::string what = std::to_string(iterations) + " iterations on " + GetParam();
    const Frame frame =
        render(onBackend(with(kSmall, {"propagation.iterations=" + std::to_string(iterations)})));
    expectSound(frame, what);
    EXPECT_GT(sum(frame.outputs.at("indirect")), 0.0) << what;  // the injected light itself
  }
}

TEST_P(ExtremeMatrix, AOneTexelRsmAndAOnePixelOutput) {
  const Frame tiny = render(onBackend(with(kSmall, {"light_maps.rsm_resolution=1"})));
  expectSound(tiny, "RSM 1^2 on " + GetParam());
  const Frame pixel = render(onBackend(with(kSmall, {"output.width=1", "output.height=1"})));
  expectSound(pixel, "output 1x1 on " + GetParam());
  EXPECT_EQ(pixel.outputs.at("combined").width * pixel.outputs.at("combined").height, 1);
}

INSTANTIATE_TEST_SUITE_P(Backends, ExtremeMatrix, ::testing::Values("gl", "cpu"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace lpvlab
