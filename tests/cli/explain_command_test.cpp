// `lpvlab explain` as a user runs it, on a small Cornell box: it writes explain.json and
// explain.exr; its budget's terms add up to the total; its "method" image is the run's own indirect
// image and its grid.npy the run's own grid dump, beside an exact grid of the same shape; a finished explanation is not replaced without --force; and what it cannot explain (a
// method without a light grid, light the oracles do not model) is refused by name before any
// reference is rendered.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "executable_support.h"
#include "framework/io/image.h"
#include "framework/io/npy.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;
using test::quoted;

const std::string kSmall =
    " -s output.width=48 -s output.height=48 -s grid.resolution=12 -s propagation.iterations=12"
    " -s light_maps.rsm_resolution=64 -s reference.samples=16";

double number(const nlohmann::json& value) { return value.get<double>(); }

TEST(ExplainCommand, WritesABudgetWhoseTermsAddUpAndTheRunsOwnImage) {
  test::TempDir dir;
  const fs::path out = dir.path() / "explained";
  const test::LpvlabResult r =
      test::runLpvlab("explain --vpls 256" + kSmall + " --out " + quoted(out.string()), dir.path(), dir.path());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("propagation"), std::string::npos) << r.out;
  const nlohmann::json result = nlohmann::json::parse(test::readFile(out / "explain.json"));
  const nlohmann::json& budget = result["budgets"]["indirect_vs_indirect1"];
  double removed = 0.0;
  std::vector<std::string> stages;
  for (const nlohmann::json& term : budget["terms"]) {
    removed += number(term["block_nrmse_reduction"]);
    stages.push_back(term["stage"]);
  }
  EXPECT_EQ(stages, (std::vector<std::string>{"propagation", "rendering", "occlusion", "injection"}));
  EXPECT_NEAR(removed, number(budget["total"]["block_nrmse"]), 1e-9);
  EXPECT_GT(number(budget["total"]["block_nrmse"]), 0.0);
  EXPECT_LE(number(result["vpls"]["per_draw"]), 256.0);
  EXPECT_EQ(result["vpls"]["draws"], 2);
  // The oracles see the same light as LPV: their means within a factor 2 of its.
  for (const char* image : {"grid", "gather", "gather_visible"}) {
    const double ratio = number(budget["images"][image]["mean_ratio"]) / number(budget["images"]["method"]["mean_ratio"]);
    EXPECT_GT(ratio, 0.5) << image;
    EXPECT_LT(ratio, 2.0) << image;
  }

  // The chain's "method" is what `lpvlab run` renders with the same settings (CPU kernels: exactly).
  const fs::path run = dir.path() / "run";
  const test::LpvlabResult ran = test::runLpvlab(
      "run" + kSmall + " -s timing.warmup=0 -s timing.repeats=1 -s output.dump_grid=true --out " +
          quoted(run.string()),
      dir.path(), dir.path());
  ASSERT_EQ(ran.exitCode, 0) << ran.err;
  const std::vector<NamedImage> layers = readExr((out / "explain.exr").string());
  const Image& lpv = findAov(layers, "method");
  const Image& indirect = findAov(readExr((run / "images.exr").string()), "indirect");
  ASSERT_EQ(lpv.pixels.size(), indirect.pixels.size());
  for (std::size_t i = 0; i < lpv.pixels.size(); ++i) ASSERT_EQ(lpv.pixels[i], indirect.pixels[i]) << i;
  for (const char* name : {"reference_indirect1", "grid", "grid_visible", "gather", "gather_visible", "depth"})
    EXPECT_NE(findAovOrNull(layers, name), nullptr) << name;
  // Its grid is the run's grid dump, value for value; the exact grid has its shape, and (no GV
  // here, so no visibility) every cell's DC coefficient of every channel, the intensity averaged
  // over directions, is >= 0, and the grid holds light.
  const NpyArray grid = readNpy((out / "grid.npy").string()), ran_grid = readNpy((run / "grid.npy").string());
  ASSERT_EQ(grid.shape, ran_grid.shape);
  for (std::size_t i = 0; i < grid.values.size(); ++i) ASSERT_EQ(grid.values[i], ran_grid.values[i]) << i;
  const NpyArray exact = readNpy((out / "exact_grid.npy").string());
  ASSERT_EQ(exact.shape, grid.shape);  // level, channel, coefficient, z, y, x
  const std::size_t cells = grid.shape[3] * grid.shape[4] * grid.shape[5], coefficients = grid.shape[2];
  double dc = 0.0;
  for (std::size_t level = 0; level < grid.shape[0]; ++level)
    for (std::size_t channel = 0; channel < 3; ++channel)
      for (std::size_t cell = 0; cell < cells; ++cell) {
        const float c0 = exact.values[((level * 3 + channel) * coefficients) * cells + cell];
        ASSERT_GE(c0, 0.0f) << cell;
        dc += c0;
      }
  EXPECT_GT(dc, 0.0);
  EXPECT_EQ(result["outputs"]["exact_grid"]["npy"], "exact_grid.npy");

  // A finished explanation stays unless --force.
  const test::LpvlabResult again =
      test::runLpvlab("explain" + kSmall + " --out " + quoted(out.string()), dir.path(), dir.path());
  EXPECT_EQ(again.exitCode, 1);
  EXPECT_NE(again.err.find("explain.json"), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
}

TEST(ExplainCommand, RefusesWhatItCannotExplainByName) {
  test::TempDir dir;
  const test::LpvlabResult method = test::runLpvlab(
      "explain -s indirect.method=instant_radiosity --out " + quoted((dir.path() / "a").string()), dir.path(), dir.path());
  EXPECT_EQ(method.exitCode, 1);
  EXPECT_NE(method.err.find("no light grid"), std::string::npos) << method.err;
  EXPECT_FALSE(fs::exists(dir.path() / "a" / "explain.json"));

  std::ofstream(dir.path() / "sky.toml") << "[sky]\nradiance = [0.1, 0.1, 0.1]\n"
                                            "[[injection.also]]\ntype = \"sky_columns\"\n";
  const test::LpvlabResult sky =
      test::runLpvlab("explain sky.toml --out " + quoted((dir.path() / "b").string()), dir.path(), dir.path());
  EXPECT_EQ(sky.exitCode, 1);
  EXPECT_NE(sky.err.find("sky.toml"), std::string::npos) << sky.err;
  EXPECT_NE(sky.err.find("[injection.also[0]] type = \"sky_columns\""), std::string::npos) << sky.err;
  EXPECT_EQ(sky.err.find("reference"), std::string::npos) << "a reference was rendered first:\n" << sky.err;
}

}  // namespace
}  // namespace lpvlab
