// A run that compares itself with its reference ([reference] compare = true): the reference is
// rendered first (into a temporary cache), the manifest gets metrics and z-tests per output pair,
// and the FLIP heat map is written. The rasterised direct light must agree with the tracer's.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/experiment/run.h"
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
  EXPECT_NEAR(direct["ratio_of_means"].get<double>(), 1.0, 0.05);
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

}  // namespace
}  // namespace lpvlab
