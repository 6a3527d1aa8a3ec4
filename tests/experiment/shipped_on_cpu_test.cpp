// The shipped experiments on the CPU backend (issue 13's "done when"): the first configuration of
// every file in experiments/, made small, either is refused by `[compute] backend = "cpu"` with a
// strategy named (one without a CPU kernel yet), or renders the same images as on GL, within
// float rounding (direct light: but for rare shadow comparisons, backend_comparison.h), or is a
// file for the path tracer alone, whose scene has no LPV light. Prints which run and which are
// refused, and why: the CPU backend's coverage.
// The default experiment must run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "backend_comparison.h"
#include "framework/core/error.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/scene_cache.h"
#include "framework/experiment/sweep_expansion.h"
#include "framework/pipeline/pipeline.h"
#include "io/temp_dir.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kSmall = {
    "output.width=48", "output.height=48", "light_maps.rsm_resolution=32",
    "light_maps.shadow_resolution=128", "timing.warmup=0", "timing.repeats=1"};

struct Rendered {
  Image direct, indirect;
};

// Every shipped file's scene read once (Sponza is several seconds a load; most files share it).
SceneCache& scenes() {
  static SceneCache cache;
  return cache;
}

Rendered render(const std::string& file, const std::string& backend) {
  std::vector<std::string> overrides = kSmall;
  overrides.push_back("compute.backend=\"" + backend + "\"");
  Experiment e = loadExperiment(file, overrides, std::ref(scenes()));
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  const std::vector<NamedImage> aovs = pipeline.readOutputs();
  return {findAov(aovs, "direct"), findAov(aovs, "indirect")};
}

TEST(ShippedOnCpu, EachShippedExperimentRunsOnTheCpuAsOnGlOrIsRefusedByName) {
  test::glTestContext();
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(LPVLAB_SOURCE_DIR) / "experiments"))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  test::TempDir dir;
  std::vector<std::string> ran, refused;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    const std::vector<SweepConfiguration> sweep = expandSweep(file.string());
    ASSERT_FALSE(sweep.empty());
    const fs::path first = dir.path() / (file.stem().string() + ".toml");
    std::ofstream(first) << configurationToml(file.string(), sweep.front());
    try {
      loadExperiment(first.string(), {"compute.backend=\"cpu\""}, std::ref(scenes()));
    } catch (const Error& error) {
      const std::string why = error.what();
      EXPECT_NE(why.find("cannot run on the CPU backend"), std::string::npos) << why;
      const std::size_t strategy = why.find(": [");  // past the temporary file's name
      const std::size_t end = why.find(" ([compute]");
      refused.push_back(file.filename().string() +
                        why.substr(strategy == std::string::npos ? 0 : strategy, end - strategy));
      continue;
    }
    Rendered cpu, gl;
    try {
      cpu = render(first.string(), "cpu");
      gl = render(first.string(), "gl");
    } catch (const Error& error) {  // a file for the path tracer alone: no LPV light
      const std::string why = error.what();
      EXPECT_NE(why.find("no light the indirect method \"lpv\" can use"), std::string::npos) << why;
      refused.push_back(file.filename().string() + ": not an LPV experiment (no LPV light)");
      continue;
    }
    test::expectSameImage(cpu.indirect, gl.indirect, "indirect");
    test::expectSameDirectLight(cpu.direct, gl.direct, "direct");
    ran.push_back(file.filename().string());
  }
  std::cout << "[ cpu backend ] " << ran.size() << " of " << files.size()
            << " shipped experiments (first configuration) run on the CPU backend:";
  for (const std::string& name : ran) std::cout << " " << name;
  std::cout << "\n[ cpu backend ] refused:\n";
  for (const std::string& why : refused) std::cout << "  " << why << "\n";
  EXPECT_NE(std::find(ran.begin(), ran.end(), "cornell_box.toml"), ran.end());
}

}  // namespace
}  // namespace lpvlab
