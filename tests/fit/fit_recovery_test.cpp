// Fits against references made by lpvlab's own LPV pipeline with known, perturbed constants (plus
// seeded Gaussian noise of 2% of the mean, as a path-traced reference has noise): the fit
// recovers the constant within its reported uncertainty, keeps to its bounds, and reports a
// parameter without effect as undetermined.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "fit/fit_test_support.h"
#include "fit/synthetic_views.h"
#include "framework/experiment/experiment.h"
#include "framework/fit/fit_output.h"
#include "framework/pipeline/pipeline.h"
#include "framework/fit/fit_problem.h"
#include "gl/gl_test_context.h"

namespace lpvlab {
namespace {

TEST(FitRecovery, RecoversAPerturbedDampingWithinItsUncertainty) {
  test::glTestContext();
  test::FitFiles files("recovery");
  const FitSpec spec = test::smallFitSpec(files, 16,
      "parameters = [{ key = \"propagation.damping\", initial = 1.0, lower = 0.5, upper = 1.5 }]\n"
      "tile = 4\n");  // 256 tiles: the sandwich's own spread is about 5%
  const double truth = 0.85;
  FitEvaluator evaluator(spec, test::syntheticViews(spec, {truth}));
  const FitResult result = runFit(evaluator);
  ASSERT_FALSE(result.undetermined[0]);
  EXPECT_FALSE(result.atBound[0]);
  EXPECT_TRUE(result.converged) << result.termination;
  EXPECT_LT(result.stdDev[0], 0.01);  // the images determine it well
  EXPECT_GT(result.stdDev[0], 0.0);
  EXPECT_LE(std::abs(result.values[0] - truth), 3.0 * result.stdDev[0])
      << result.values[0] << " +- " << result.stdDev[0];
  EXPECT_LT(result.finalCost, 0.1 * result.initialCost);
  // The only errors left are the targets' independent noise: the tiled sandwich deviation then
  // agrees with Ceres's.
  EXPECT_NEAR(result.sandwichStdDev[0] / result.stdDev[0], 1.0, 0.2)
      << result.sandwichStdDev[0] << " against " << result.stdDev[0];
  RecordProperty("fitted", std::to_string(result.values[0]) + " +- " + std::to_string(result.stdDev[0]) +
                               " (sandwich " + std::to_string(result.sandwichStdDev[0]) + ")");
  ASSERT_GE(result.log.size(), 2u);
  EXPECT_EQ(result.log.front().x[0], 1.0);
}

// Automatic derivatives (dual numbers through the frames) and central differences lead the fit
// to the same constant, and each parameter says which it got (the shift cannot be differentiated).
TEST(FitRecovery, AutomaticAndCentralDerivativesFindTheSameConstant) {
  test::glTestContext();
  test::FitFiles files("derivatives");
  FitResult results[2];
  for (const bool central : {false, true}) {
    const FitSpec spec = test::smallFitSpec(
        files, 16,
        std::string("parameters = [{ key = \"propagation.damping\", initial = 1.0, lower = 0.5, "
                    "upper = 1.5 }, { key = \"injection.shift\", lower = 0.0, upper = 3.0, "
                    "step = 0.25 }]\n") +
            (central ? "derivatives = \"central\"\n" : ""));
    FitEvaluator evaluator(spec, test::syntheticViews(spec, {0.85, 1.0}));
    results[central] = runFit(evaluator);
  }
  const FitResult &automatic = results[0], &central = results[1];
  ASSERT_EQ(automatic.derivatives.size(), 2u);
  EXPECT_EQ(automatic.derivatives[0], "");  // damping: automatic
  EXPECT_NE(automatic.derivatives[1].find("carries no derivatives of 'shift'"), std::string::npos)
      << automatic.derivatives[1];
  EXPECT_NE(central.derivatives[0].find("central"), std::string::npos) << central.derivatives[0];
  ASSERT_FALSE(automatic.undetermined[0]);
  ASSERT_FALSE(central.undetermined[0]);
  EXPECT_LT(std::abs(automatic.values[0] - central.values[0]), 0.1 * central.stdDev[0])
      << automatic.values[0] << " against " << central.values[0] << " +- " << central.stdDev[0];
  EXPECT_LE(automatic.finalCost, central.finalCost * (1.0 + 1e-3));
}

TEST(FitRecovery, KeepsToItsBounds) {
  test::glTestContext();
  test::FitFiles files("bounds");
  const FitSpec spec = test::smallFitSpec(files, 16,
      "parameters = [{ key = \"propagation.damping\", initial = 1.0, lower = 0.9, upper = 1.2 }]\n"
      "max_iterations = 10\n");
  FitEvaluator evaluator(spec, test::syntheticViews(spec, {0.7}));  // the truth lies below the bound
  const FitResult result = runFit(evaluator);
  EXPECT_NEAR(result.values[0], 0.9, 1e-9);
  EXPECT_TRUE(result.atBound[0]);
  for (const std::vector<double>& x : evaluator.evaluated()) {
    EXPECT_GE(x[0], 0.9);
    EXPECT_LE(x[0], 1.2);
  }
}

TEST(FitRecovery, AParameterWithoutEffectIsUndetermined) {
  test::glTestContext();
  test::FitFiles files("undetermined");
  // Without propagation iterations the damping changes nothing; the rendering's normal offset
  // (where the grid is read) does.
  const FitSpec spec = test::smallFitSpec(files, 0,
      "parameters = [{ key = \"propagation.damping\", lower = 0.5, upper = 1.5 },\n"
      "              { key = \"rendering.normal_offset\", lower = -0.5, upper = 1.0 }]\n"
      "max_iterations = 10\n");
  FitEvaluator evaluator(spec, test::syntheticViews(spec, {0.8, 0.3}));
  const FitResult result = runFit(evaluator);
  EXPECT_TRUE(result.undetermined[0]);
  EXPECT_TRUE(std::isnan(result.stdDev[0]));
  EXPECT_TRUE(std::isnan(result.sandwichStdDev[0]));
  EXPECT_GT(result.sandwichStdDev[1], 0.0);
  ASSERT_FALSE(result.undetermined[1]) << "singular values " << nlohmann::json(result.singularValues)
                                       << ", normal_offset " << result.values[1] << ", " << result.termination;
  EXPECT_LE(std::abs(result.values[1] - 0.3), 3.0 * result.stdDev[1])
      << result.values[1] << " +- " << result.stdDev[1];
  const std::string toml = fittedToml(spec, result);
  EXPECT_EQ(toml.find("damping ="), std::string::npos) << toml;
  EXPECT_NE(toml.find("normal_offset ="), std::string::npos) << toml;
}

// The constants exposed for fitting act as documented: trilinear's `scale` multiplies the
// indirect light (by 2: exactly, in floating point).
TEST(FitConstants, TrilinearScaleMultipliesTheIndirectLight) {
  test::glTestContext();
  test::FitFiles files("scale");
  const FitSpec spec = test::smallFitSpec(files, 4, "parameters = [{ key = \"rendering.scale\" }]\n");
  ASSERT_EQ(spec.parameters[0].initial, 1.0);
  FitEvaluator evaluator(spec, {FitView{"main", false, spec.viewTable(spec.views[0]), Image(64, 64, 3)}});
  const Image one = evaluator.render(evaluator.views()[0], {1.0}).indirect;
  const Image two = evaluator.render(evaluator.views()[0], {2.0}).indirect;
  // Injection adds VPLs with float atomics in any order, so two renderings agree to rounding only.
  double sum = 0.0, largest = 0.0;
  for (const float v : one.pixels) largest = std::max(largest, double(std::abs(v)));
  for (std::size_t i = 0; i < one.pixels.size(); ++i) {
    ASSERT_NEAR(two.pixels[i], 2.0f * one.pixels[i], 1e-5 * largest) << "value " << i;
    sum += one.pixels[i];
  }
  EXPECT_GT(sum, 0.0);
}

// The GV's blocking_scale acts on the image (the transmittance clamp(1 - B, 0, 1) is not
// saturated everywhere): at 0 the GV blocks nothing, as without occlusion; more blocking lets
// less light through.
TEST(FitConstants, GvBlockingScaleActsOnTheIndirectLight) {
  test::glTestContext();
  test::FitFiles files("blocking");
  const std::string base = test::smallCornellBox(16);
  const FitSpec spec = readFitSpec(files.write(
      "fit.toml", base + "[occlusion]\ntype = \"geometry_volume\"\n"
                         "[fit]\nparameters = [{ key = \"occlusion.blocking_scale\" }]\n"
                         "[[fit.views]]\nname = \"main\"\n"));
  ASSERT_EQ(spec.parameters[0].initial, 1.0);
  FitEvaluator evaluator(spec, {FitView{"main", false, spec.viewTable(spec.views[0]), Image(64, 64, 3)}});
  const auto total = [](const Image& image) {
    double sum = 0.0;
    for (const float v : image.pixels) sum += v;
    return sum;
  };
  const Image zero = evaluator.render(evaluator.views()[0], {0.0}).indirect;
  const double one = total(evaluator.render(evaluator.views()[0], {1.0}).indirect);
  const double three = total(evaluator.render(evaluator.views()[0], {3.0}).indirect);
  Experiment open = loadExperiment(files.write("open.toml", base));
  ShaderCompiler shaders;
  Pipeline pipeline(open.scene, open.camera, open.settings, std::move(open.method), shaders);
  pipeline.renderFrame();
  const Image none = findAov(pipeline.readOutputs(), "indirect");
  double largest = 0.0;
  for (const float v : none.pixels) largest = std::max(largest, double(std::abs(v)));
  for (std::size_t i = 0; i < none.pixels.size(); ++i)
    ASSERT_NEAR(zero.pixels[i], none.pixels[i], 1e-5 * largest) << "value " << i;
  EXPECT_LT(one, 0.99 * total(zero));
  EXPECT_LT(three, 0.99 * one);
  std::cout << "[ fit ] indirect light summed: blocking_scale 0: " << total(zero) << ", 1: " << one
            << ", 3: " << three << "\n";
}

}  // namespace
}  // namespace lpvlab
