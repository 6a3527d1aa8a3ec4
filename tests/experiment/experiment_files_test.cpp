// Every experiment file shipped in experiments/ loads: its sweep expands, and every configuration
// it expands to is a valid experiment (strategies, their parameters, the composition's
// requirements, the scene). A file that drifts from the strategies it names fails here, not in a
// user's hour-long sweep. Scenes are loaded once per file and configuration, so this is slowish.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "lpv_support.h"
#include "framework/core/error.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/scene_cache.h"
#include "framework/experiment/sweep_expansion.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> experimentFiles() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(LPVLAB_SOURCE_DIR) / "experiments"))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ExperimentFiles, EveryConfigurationOfEveryShippedFileLoads) {
  const std::vector<fs::path> files = experimentFiles();
  ASSERT_GE(files.size(), 10u);
  test::TempDir dir;
  SceneCache scenes;  // each scene read once: most files share Sponza, Sibenik or the box
  int configurations = 0;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    try {
      const std::vector<SweepConfiguration> sweep = expandSweep(file.string());
      ASSERT_FALSE(sweep.empty());
      for (const SweepConfiguration& configuration : sweep) {
        const fs::path resolved = dir.path() / (configuration.id + ".toml");
        std::ofstream(resolved) << configurationToml(file.string(), configuration);
        const Experiment e = loadExperiment(resolved.string(), {}, std::ref(scenes));
        ASSERT_TRUE(e.method);
        if (const auto* lpv = dynamic_cast<const LightPropagationVolumes*>(e.method.get())) {
          EXPECT_FALSE(lpv->strategies().injection.empty());
        }
        ++configurations;
      }
    } catch (const Error& error) {
      ADD_FAILURE() << error.what();
    }
  }
  std::cout << "[ experiments ] " << files.size() << " files, " << configurations
            << " configurations loaded\n";
}

}  // namespace
}  // namespace lpvlab
