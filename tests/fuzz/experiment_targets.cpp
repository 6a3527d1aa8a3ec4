// Fuzz targets of the TOML that users write: experiment files (extends, include, [sweep]), fit
// files, and -s overrides.

#include <string>

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/experiment_file.h"
#include "framework/experiment/sweep_check.h"
#include "framework/experiment/sweep_expansion.h"
#include "framework/fit/fit_spec.h"
#include "fuzz/fuzz_targets.h"
#include "fuzz/fuzz_workspace.h"

namespace lpvlab::fuzz {

void experimentFile(Bytes data, std::size_t size) {
  // In experiments/, so that `extends = "cornell_box.toml"` of a seed finds its base.
  const std::string path = FuzzWorkspace::instance().write("experiments/fuzzed.toml", data, size);
  try {
    toml::table root = readExperimentTable(path);
    const std::vector<SweepConfiguration> configurations = expandSweep(root, path);
    sweptKeys(root, path);
    checkConfigurations(root, path, configurations);
    for (const SweepConfiguration& c : configurations) configurationToml(path, c);
  } catch (const Error&) {
  }
}

void fitFile(Bytes data, std::size_t size) {
  const std::string path =
      FuzzWorkspace::instance().write("experiments/fuzzed_fit.toml", data, size);
  try {
    const FitSpec spec = readFitSpec(path);
    for (const FitViewSpec& view : spec.views) spec.viewTable(view);
  } catch (const Error&) {
  }
}

void overrides(Bytes data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    toml::table root;
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      applyOverride(root, std::string_view(text).substr(start, end - start));
      start = end + 1;
    }
    loadExperiment(root, "");
  } catch (const Error&) {
  }
}

}  // namespace lpvlab::fuzz
