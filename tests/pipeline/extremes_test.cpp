// Numerical extremes of a whole frame: lights 1e-9 and 1e9 times the default (the pipeline is
// linear in the light, so every output must scale by exactly that factor, up to float rounding,
// with no NaN, Inf or flush to zero), a one-cell grid, and a scene with a degenerate triangle.

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

const std::vector<std::string> kSmall = {"output.width=64", "output.height=64", "timing.warmup=0",
                                         "grid.resolution=16", "propagation.iterations=16"};

std::map<std::string, Image> render(Experiment& e) {
  test::glTestContext();
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  std::map<std::string, Image> out;
  for (NamedImage& aov : pipeline.readOutputs()) out[aov.name] = std::move(aov.image);
  return out;
}

void expectFinite(const Image& image, const std::string& what) {
  for (float v : image.pixels) ASSERT_TRUE(std::isfinite(v)) << what;
}

std::map<std::string, Image> renderWithIntensityScale(float scale) {
  Experiment e = loadExperiment("", kSmall);
  for (Light& light : e.scene.lights) light.intensity *= scale;
  return render(e);
}

TEST(Extremes, OutputsScaleLinearlyFromVeryDimToVeryBrightLights) {
  const auto reference = renderWithIntensityScale(1.0f);
  for (float scale : {1e-9f, 1e9f}) {
    const auto scaled = renderWithIntensityScale(scale);
    for (const char* name : {"direct", "indirect"}) {
      const Image& a = reference.at(name);
      const Image& b = scaled.at(name);
      expectFinite(b, name);
      double sumA = 0.0, sumB = 0.0, worst = 0.0;
      for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        sumA += a.pixels[i];
        sumB += b.pixels[i];
        if (a.pixels[i] > 1e-6f)
          worst = std::max(worst, std::abs(b.pixels[i] / (scale * a.pixels[i]) - 1.0));
      }
      ASSERT_GT(sumA, 0.0) << name;
      EXPECT_NEAR(sumB / (scale * sumA), 1.0, 1e-4) << name << " at scale " << scale;
      EXPECT_LT(worst, 1e-3) << name << " at scale " << scale;
    }
  }
}

TEST(Extremes, AOneCellGridGivesFiniteIndirectLight) {
  // Half a cell of shift: a whole cell would move every VPL of the box's walls (which lie on the
  // one cell's faces) onto the opposite face, where it goes to the cell outside (grid.glsl's
  // surfaceCell bins a point on a boundary along its normal).
  Experiment e = loadExperiment("", {"output.width=32", "output.height=32", "grid.resolution=1",
                                     "grid.margin=0", "propagation.iterations=3",
                                     "injection.shift=0.5"});
  EXPECT_EQ(e.settings.grid.cellCount(), 1);
  const auto out = render(e);
  expectFinite(out.at("indirect"), "indirect");
  double sum = 0.0;
  for (float v : out.at("indirect").pixels) sum += v;
  EXPECT_GT(sum, 0.0);  // the injected light of the one cell is still read back
}

TEST(Extremes, ADegenerateTriangleDoesNotPoisonTheImage) {
  // A floor quad, a wall and one zero-area triangle (three collinear points) facing the light.
  const auto dir = std::filesystem::temp_directory_path() / "lpvlab_degenerate";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "scene.obj") << "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
                                      "v -1 0 1\nv 1 0 1\nv 1 2 1\nv -1 2 1\n"
                                      "v 0 0.5 0\nv 0.1 0.5 0\nv 0.2 0.5 0\n"
                                      "f 1 2 3\nf 1 3 4\nf 5 6 7\nf 5 7 8\nf 9 10 11\n";
  std::ofstream(dir / "experiment.toml")
      << "[scene]\nfile = \"scene.obj\"\n"
         "[[lights]]\ntype = \"point\"\nposition = [0.0, 1.5, -0.5]\nintensity = 1.0\n"
         "[camera]\nposition = [0.0, 1.0, -3.0]\nlook_at = [0.0, 0.5, 0.0]\nfov_deg = 60.0\n";
  Experiment e = loadExperiment((dir / "experiment.toml").string(), kSmall);
  ASSERT_EQ(e.scene.triangleCount(), 5u);  // the degenerate triangle reaches the pipeline
  const auto out = render(e);
  for (const auto& [name, image] : out) expectFinite(image, name);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lpvlab
