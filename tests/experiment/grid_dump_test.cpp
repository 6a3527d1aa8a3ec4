// [output] dump_grid (lpvlab run --dump-grid): the run writes the method's light grid after its
// last frame as grid.npy (numpy.load reads it) with grid.json (axes, shape, units, where each
// level's cells are). What must hold:
//   - the file is every level's accumulated grid as LPV holds it, levels stacked finest first, in
//     the axes grid.json names (against the method's own read-back of each level);
//   - the grid is linear in the light: doubling the light's intensity doubles every coefficient;
//   - numpy reads it (when python3-numpy is installed: shape and a checksum agree);
//   - a method without a light grid, or an animated experiment, is refused naming the key.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/experiment/run.h"
#include "framework/io/npy.h"
#include "error_support.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kSmall = {"output.width=32", "output.height=32", "grid.resolution=8",
                                         "propagation.iterations=4", "cascades.levels=2",
                                         "timing.warmup=0", "timing.repeats=1", "output.dump_grid=true"};

NpyArray dumpOf(const fs::path& dir, float intensityScale, nlohmann::json* manifest = nullptr) {
  const GlContext& context = test::glTestContext();
  Experiment e = loadExperiment("", kSmall);
  for (Light& light : e.scene.lights) light.intensity *= intensityScale;
  const nlohmann::json m = runExperiment(e, context, dir.string());
  if (manifest) *manifest = m;
  return readNpy((dir / "grid.npy").string());
}

TEST(GridDump, HoldsEveryLevelsAccumulatedGridLinearInTheLight) {
  const fs::path dir = fs::temp_directory_path() / ("lpvlab_grid_dump_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  nlohmann::json manifest;
  const NpyArray once = dumpOf(dir / "once", 1.0f, &manifest);
  const NpyArray twice = dumpOf(dir / "twice", 2.0f);

  std::ifstream in(dir / "once" / "grid.json");
  const nlohmann::json described = nlohmann::json::parse(in);
  EXPECT_EQ(described["axes"], (std::vector<std::string>{"level", "channel", "coefficient", "z", "y", "x"}));
  EXPECT_EQ(described["shape"].get<std::vector<std::size_t>>(), once.shape);
  EXPECT_EQ(manifest["outputs"]["grid"]["npy"], "grid.npy");
  ASSERT_EQ(once.shape.size(), 6u);
  EXPECT_EQ(once.shape[0], 2u) << "two cascade levels";
  EXPECT_EQ(once.shape[1], 3u);
  EXPECT_EQ(once.shape[2], 4u) << "SH order 1";
  const auto& levels = described["levels"];
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_LT(levels[0]["cell_size_m"].get<double>(), levels[1]["cell_size_m"].get<double>())
      << "finest first";

  // Each level's block against a frame of the same experiment read back by LPV itself.
  const GlContext& context = test::glTestContext();
  (void)context;
  Experiment e = loadExperiment("", kSmall);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  const GridDump dump = pipeline.method().dumpGrid();
  ASSERT_EQ(dump.values.size(), once.values.size());
  const std::size_t perLevel = once.values.size() / once.shape[0];
  double largest = 0.0;
  for (float v : once.values) largest = std::max(largest, double(std::abs(v)));
  ASSERT_GT(largest, 0.0) << "a lit box has light in its grid";
  for (std::size_t i = 0; i < once.values.size(); ++i) {
    ASSERT_NEAR(once.values[i], dump.values[i], 1e-6 * largest) << "value " << i << ", level " << i / perLevel;
    ASSERT_NEAR(twice.values[i], 2.0f * once.values[i], 1e-5 * largest) << "value " << i;
  }
  // numpy reads it, where it is installed (the checksum is the same sum in double).
  double sum = 0.0;
  for (float v : once.values) sum += v;
  const std::string script = "/usr/bin/python3 -c \"import numpy as n; a = n.load('" +
                             (dir / "once" / "grid.npy").string() +
                             "'); print(a.shape, repr(float(a.astype(n.float64).sum())))\" > " +
                             (dir / "numpy.txt").string() + " 2>/dev/null";
  if (std::system(script.c_str()) == 0) {
    std::ifstream out(dir / "numpy.txt");
    std::string line;
    std::getline(out, line);
    EXPECT_EQ(line.substr(0, line.find(')') + 1), "(2, 3, 4, 8, 8, 8)");
    EXPECT_NEAR(std::stod(line.substr(line.find(')') + 2)), sum, 1e-9 * std::abs(sum) + 1e-12);
  }
  fs::remove_all(dir);
}

TEST(GridDump, IsRefusedWithoutALightGridOrForAnAnimatedRun) {
  std::vector<std::string> otherMethod = kSmall;
  otherMethod.push_back("indirect.method=\"instant_radiosity\"");
  const std::string noGrid = test::errorOf([&] { loadExperiment("", otherMethod); });
  EXPECT_TRUE(test::contains(noGrid, "output.dump_grid"));
  EXPECT_TRUE(test::contains(noGrid, "keeps no light grid"));
  const std::string animated = test::errorOf([&] {
    loadExperiment(LPVLAB_SOURCE_DIR "/experiments/cornell_box_moving_light.toml", {"output.dump_grid=true"});
  });
  EXPECT_TRUE(test::contains(animated, "only a static run"));
}

}  // namespace
}  // namespace lpvlab
