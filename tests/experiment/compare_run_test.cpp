// A run that compares itself with its reference ([reference] compare = true): the reference is
// rendered first (into a temporary cache), the manifest gets metrics and z-tests per output pair,
// and the FLIP heat map is written. The rasterised direct light must agree with the tracer's.
// The reference's noise floor (metric noise_floor_rmse) is its own RMSE.

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "error_support.h"
#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/experiment/run.h"
#include "framework/experiment/run_outputs.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

TEST(CompareRun, RendersTheMissingReferenceAndRecordsMetricsAndAHeatMap) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_compare_run";
  fs::remove_all(dir);
  Experiment e = loadExperiment("", {"output.width=48", "output.height=48", "grid.resolution=16",
                                     "propagation.iterations=16", "timing.warmup=0",
                                     "timing.repeats=1", "reference.compare=true",
                                     "reference.samples=64"});
  e.reference.cacheDir = (dir / "cache").string();
  e.reference.showProgress = false;
  const nlohmann::json manifest = runExperiment(e, context, (dir / "run").string());

  ASSERT_TRUE(manifest.contains("reference"));
  EXPECT_EQ(manifest["reference"]["samples"].get<int>(), 64);
  EXPECT_TRUE(fs::exists(manifest["reference"]["directory"].get<std::string>() + "/images.exr"));
  const auto& direct = manifest["reference"]["comparison"]["direct_vs_direct"];
  EXPECT_NEAR(direct["metrics"]["ratio_of_means"].get<double>(), 1.0, 0.05);
  EXPECT_GT(direct["metrics"]["ssim"].get<double>(), 0.8);
  EXPECT_LT(direct["metrics"]["flip"].get<double>(), 0.2);
  const auto& indirect = manifest["reference"]["comparison"]["indirect_vs_indirect1"];
  for (const char* metric : {"mae", "rmse", "rel_mse", "ssim", "flip"})
    EXPECT_TRUE(std::isfinite(indirect["metrics"][metric].get<double>())) << metric;
  EXPECT_GT(indirect["metrics"]["pixels"].get<int>(), 48 * 48 / 2);  // the box fills the view
  EXPECT_TRUE(fs::exists(dir / "run" / "error_indirect.png"));

  std::ifstream written(dir / "run" / "manifest.json");
  EXPECT_EQ(nlohmann::json::parse(written)["reference"]["key"], manifest["reference"]["key"]);
  fs::remove_all(dir);
}

TEST(CompareRun, PairsAndRegionsAreConfigurable) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_compare_pairs";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "e.toml") << "[output]\nwidth = 32\nheight = 32\n"
                                   "[grid]\nresolution = 8\n[propagation]\niterations = 4\n"
                                   "[timing]\nwarmup = 0\nrepeats = 1\n"
                                   "[reference]\ncompare = true\nsamples = 16\n"
                                   "[metrics]\npairs = [\"combined:combined\"]\n"
                                   "[[metrics.regions]]\nname = \"left\"\nright = 0.5\n"
                                   "[[metrics.regions]]\nname = \"top strip\"\nbottom = 0.01\n";
  Experiment e = loadExperiment((dir / "e.toml").string());
  e.reference.cacheDir = (dir / "cache").string();
  e.reference.showProgress = false;
  const nlohmann::json manifest = runExperiment(e, context, (dir / "run").string());
  const auto& comparison = manifest["reference"]["comparison"];
  ASSERT_EQ(comparison.size(), 1u);
  const auto& pair = comparison["combined_vs_combined"];
  const int all = pair["metrics"]["pixels"].get<int>();
  const int left = pair["regions"]["left"]["pixels"].get<int>();
  EXPECT_GT(left, 0);
  EXPECT_LT(left, all);
  // A strip thinner than a pixel holds no pixel centre: no figures, and the run still succeeds.
  EXPECT_TRUE(pair["regions"]["top strip"].is_null());
  EXPECT_TRUE(fs::exists(dir / "run" / "error_combined.png"));
  fs::remove_all(dir);
}

TEST(CompareRun, BadPairsAndRegionsAreNamed) {
  const auto message = [](const std::vector<std::string>& overrides) {
    return test::errorOf([&] { loadExperiment("", overrides); });
  };
  EXPECT_NE(message({"metrics.pairs=[\"indirect:indirect2\"]"}).find("metrics.pairs"),
            std::string::npos);
  EXPECT_NE(message({"metrics.pairs=[]"}).find("names no pair"), std::string::npos);
  EXPECT_NE(message({"metrics.regions=[{name = \"r\", left = 0.6, right = 0.4}]"}).find("is empty"),
            std::string::npos);
  EXPECT_NE(message({"metrics.regions=[{name = \"r\", left = 1.5}]"}).find("metrics.regions[0].left"),
            std::string::npos);
}

}  // namespace
}  // namespace lpvlab

namespace lpvlab {
namespace {

// The reference's noise floor (run_outputs.h): the root of the mean variance of its pixel means
// over the covered pixels and channels, whatever the uncovered pixels hold.
TEST(CompareRun, TheNoiseFloorIsTheReferencesOwnRmse) {
  const int w = 8, h = 4;
  Image mask(w, h, 1, 1.0f), mean(w, h, 3, 0.5f), variance(w, h, 3, 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        // Covered: variances 1e-4 and 4e-4 alternating (mean 2.5e-4); uncovered: huge.
        const bool covered = x < w / 2;
        variance.at(x, y, c) = covered ? ((x + y + c) % 2 ? 4e-4f : 1e-4f) : 1e3f;
        if (!covered) mask.at(x, y, 0) = 0.0f;
      }
  Reference ref;
  ref.aovs = {{"indirect1", mean}, {"indirect1_variance", variance}};
  ComparisonSettings settings;
  settings.pairs = {{"indirect", "indirect1"}};
  const nlohmann::json out = compareWithReference({{"indirect", mean}}, ref, mask, settings);
  const auto& metrics = out["comparison"]["indirect_vs_indirect1"]["metrics"];
  EXPECT_NEAR(metrics["noise_floor_rmse"].get<double>(), std::sqrt(2.5e-4), 1e-7);
  EXPECT_EQ(metrics["rmse"].get<double>(), 0.0);  // the run equals the reference's mean
}

// The standard error of the reference's image mean (every pixel and channel), relative to the
// mean (0.5 here): with variance v in
// every value and a pixel's channels fully correlated, sqrt(P (3 sqrt(v))^2) / (3 P) = sqrt(v / P).
// Varying the variances across channels moves it as the bound says.
TEST(CompareRun, TheReferenceMeansStandardErrorFromItsVariances) {
  const int w = 8, h = 4;
  Image mask(w, h, 1, 1.0f), mean(w, h, 3, 0.5f), variance(w, h, 3, 4e-4f);
  ComparisonSettings settings;
  settings.pairs = {{"indirect", "indirect1"}};
  auto standardError = [&] {
    Reference ref;
    ref.aovs = {{"indirect1", mean}, {"indirect1_variance", variance}};
    return compareWithReference({{"indirect", mean}}, ref, mask, settings)["comparison"]
        ["indirect_vs_indirect1"]["metrics"]["mean_reference_relative_standard_error"].get<double>();
  };
  EXPECT_NEAR(standardError(), std::sqrt(4e-4 / (w * h)) / 0.5, 1e-7);  // relative: over 0.5
  // One channel's variance 0 everywhere: (2 sqrt(v))^2 per pixel instead of (3 sqrt(v))^2.
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) variance.at(x, y, 2) = 0.0f;
  EXPECT_NEAR(standardError(), std::sqrt(w * h * 4.0 * 4e-4) / (3.0 * w * h) / 0.5, 1e-7);
}

}  // namespace
}  // namespace lpvlab
