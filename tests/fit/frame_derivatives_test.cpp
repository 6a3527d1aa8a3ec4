// Derivatives through a whole frame (Pipeline::renderDerivatives, framework/pipeline/dual_frame.h)
// against central differences of whole frames, on the built-in Cornell box: the standard,
// directed and tetrahedral propagations, with and without the geometry volume (and its bounces),
// with respect to every parameter whose derivatives the strategies carry. The dual pass must also
// reproduce the frame it differentiates (its values are the float frame's indirect image).
//
// Central differences of float frames: step h = 3e-3 of the value (3e-3 absolute at 0). The
// float rounding of the two images (about 1e-7 of a pixel, divided by 2h) is then about 2e-5 of
// the derivative, which is what the propagation constants and the rendering's show; the GV's
// blocking scale enters every face's transmittance of every step (T^k over k steps), so its
// truncation error, of order (h k)^2, is larger: 1e-3 to 1e-4 here, 4e-3 at h = 1e-2 (it shrinks
// with h: the differences converge to the dual numbers' value). Kinks (a face flux clamped at 0, a
// transmittance clamped at 0, a cell boundary under normal_offset, leak damping's switch) put a
// few pixels off by more (one pixel of the Cornell box at 48^2 under leak damping: 25%). So the
// images are compared as a whole: the relative L2 error below 2e-3 over all values but the worst
// 0.5%, and below 5e-2 over all; and the derivative image must not be negligible (else the check
// would pass by zeros).

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "variants/resources/geometry_volume.h"
#include "gl/gl_test_context.h"

namespace lpvlab {
namespace {

// A small Cornell box frame on the CPU backend, with `extra` overrides.
std::vector<std::string> overrides(const std::vector<std::string>& extra) {
  std::vector<std::string> all = {"output.width=48",        "output.height=48",
                                  "light_maps.rsm_resolution=64",
                                  "light_maps.shadow_resolution=128",
                                  "grid.resolution=12",     "propagation.iterations=8",
                                  "compute.backend=\"cpu\""};
  all.insert(all.end(), extra.begin(), extra.end());
  return all;
}

Image indirectAt(const std::vector<std::string>& extra, ShaderCompiler& shaders) {
  Experiment e = loadExperiment("", overrides(extra));
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  for (const NamedImage& aov : pipeline.readOutputs())
    if (aov.name == "indirect") return aov.image;
  throw Error("no indirect image");
}

double norm(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum);
}

struct Seed {
  std::string key;
  double value;
};

// Every seed's derivative image against central differences, and the dual pass's values
// against the float frame.
void expectDerivativesMatchDifferences(const std::vector<std::string>& composition,
                                       const std::vector<Seed>& seeds) {
  test::glTestContext();
  ShaderCompiler shaders;
  std::vector<std::string> at = composition, keys;
  for (const Seed& s : seeds) {
    at.push_back(s.key + "=" + std::to_string(s.value));
    keys.push_back(s.key);
  }
  Experiment e = loadExperiment("", overrides(at));
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  const Pipeline::FrameDerivatives d = pipeline.renderDerivatives(keys);
  ASSERT_EQ(d.derivatives.size(), seeds.size());

  // The dual pass renders the frame it differentiates.
  const Image frame = indirectAt(at, shaders);
  std::vector<double> difference, reference;
  for (std::size_t i = 0; i < frame.pixels.size(); ++i) {
    difference.push_back(double(d.indirect.pixels[i]) - frame.pixels[i]);
    reference.push_back(frame.pixels[i]);
  }
  ASSERT_GT(norm(reference), 0.0);
  EXPECT_LT(norm(difference) / norm(reference), 1e-4) << "dual values against the float frame";

  for (std::size_t j = 0; j < seeds.size(); ++j) {
    const double h = seeds[j].value != 0.0 ? 3e-3 * std::abs(seeds[j].value) : 3e-3;
    auto shifted = [&](double sign) {
      std::vector<std::string> moved = composition;
      for (std::size_t k = 0; k < seeds.size(); ++k)
        moved.push_back(seeds[k].key + "=" +
                        std::to_string(seeds[k].value + (k == j ? sign * h : 0.0)));
      return indirectAt(moved, shaders);
    };
    const Image plus = shifted(1.0), minus = shifted(-1.0);
    std::vector<double> central, error, automatic;
    for (std::size_t i = 0; i < plus.pixels.size(); ++i) {
      central.push_back((double(plus.pixels[i]) - minus.pixels[i]) / (2.0 * h));
      automatic.push_back(d.derivatives[j].pixels[i]);
      error.push_back(automatic.back() - central.back());
      ASSERT_TRUE(std::isfinite(automatic.back())) << seeds[j].key;
    }
    EXPECT_GT(norm(central), 1e-3 * norm(reference))
        << seeds[j].key << ": the image hardly depends on it; the check would pass by zeros";
    // Without the worst 0.5% of values (the kinks, where the two need not agree).
    std::vector<std::size_t> order(error.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return std::abs(error[a]) < std::abs(error[b]); });
    order.resize(order.size() - order.size() / 200);
    std::vector<double> keptError, keptCentral;
    for (std::size_t i : order) {
      keptError.push_back(error[i]);
      keptCentral.push_back(central[i]);
    }
    EXPECT_LT(norm(keptError) / norm(keptCentral), 2e-3)
        << seeds[j].key << ": |AD - CD| / |CD| over the image but its worst 0.5% of values";
    EXPECT_LT(norm(error) / norm(central), 5e-2)
        << seeds[j].key << ": |AD - CD| / |CD| over the whole image";
  }
}

TEST(FrameDerivatives, StandardPropagationAndTrilinearRendering) {
  expectDerivativesMatchDifferences(
      {"rendering.leak_damping=1.0"},
      {{"propagation.far_face_solid_angle", 0.4},
       {"propagation.side_face_solid_angle", 0.4},
       {"propagation.damping", 0.9},
       {"rendering.leak_damping", 1.0}});
}

TEST(FrameDerivatives, RenderingConstantsAlone) {
  expectDerivativesMatchDifferences({}, {{"rendering.normal_offset", 0.3}, {"rendering.scale", 1.2}});
}

TEST(FrameDerivatives, StandardWithGeometryVolumeAndBounces) {
  expectDerivativesMatchDifferences(
      {"occlusion.type=\"geometry_volume\"", "propagation.bounces=true"},
      {{"occlusion.blocking_scale", 1.5}, {"propagation.far_face_solid_angle", 0.4}});
}

TEST(FrameDerivatives, DirectedWithGeometryVolume) {
  expectDerivativesMatchDifferences(
      {"occlusion.type=\"geometry_volume\"", "propagation.type=\"directed\""},
      {{"occlusion.blocking_scale", 1.5}});
}

TEST(FrameDerivatives, TetrahedralWithGeometryVolume) {
  expectDerivativesMatchDifferences(
      {"occlusion.type=\"geometry_volume\"", "propagation.type=\"tetrahedral\"",
       "propagation.iterations=20"},
      {{"occlusion.blocking_scale", 1.5}});
}

// On the GL backend the frame's grids and GV are GL's, read back for the dual pass.
TEST(FrameDerivatives, AFrameRenderedOnGl) {
  expectDerivativesMatchDifferences(
      {"compute.backend=\"gl\"", "occlusion.type=\"geometry_volume\""},
      {{"occlusion.blocking_scale", 1.5}, {"propagation.side_face_solid_angle", 0.4}});
}

// What cannot be differentiated is refused by name (the fit then takes central differences).
TEST(FrameDerivatives, RefusesWhatNoKernelCarries) {
  test::glTestContext();
  ShaderCompiler shaders;
  Experiment e = loadExperiment("", overrides({}));
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  EXPECT_NE(pipeline.derivativeRefusal("injection.shift").find("carries no derivatives"),
            std::string::npos);
  EXPECT_NE(pipeline.derivativeRefusal("occlusion.blocking_scale"), "");
  EXPECT_EQ(pipeline.derivativeRefusal("propagation.damping"), "");
  EXPECT_THROW(pipeline.renderDerivatives({"injection.shift"}), Error);
  EXPECT_THROW(pipeline.renderDerivatives({"rendering.scale", "rendering.scale", "rendering.scale",
                                           "rendering.scale", "rendering.scale"}),
               Error);
}

}  // namespace
}  // namespace lpvlab
