#include <iostream>

#include "framework/cli/commands.h"
#include "framework/experiment/experiment.h"
#include "framework/core/atomic_file.h"

namespace lpvlab::cli {

int referenceCommand(const Options& options) {
  Experiment experiment = loadExperiment(options.experiment, options.overrides);
  if (!options.cacheDir.empty()) experiment.reference.cacheDir = options.cacheDir;
  requireOutputDirectory(
      experiment.reference.cacheDir.empty() ? defaultCacheDir() : experiment.reference.cacheDir,
      options.cacheDir.empty() ? "reference cache" : "--cache");
  const Reference ref = ensureReference(experiment.scene, experiment.camera, experiment.reference);
  std::cout << (ref.reused ? "reused" : "rendered") << " reference " << ref.key << ": "
            << ref.samples << " spp, mean relative error " << ref.relativeError << ", "
            << ref.seconds << " s in total\n";
  if (!ref.reused) {
    const auto& session = ref.manifest["last_session"];
    std::cout << "this session: " << session["paths_per_second"].get<double>() << " paths/s, "
              << session["rays_per_second"].get<double>() << " rays/s on "
              << session["threads"].get<int>() << " threads\n";
  }
  std::cout << "wrote " << ref.directory << "/{images.exr, manifest.json, state.bin}\n";
  return 0;
}

}  // namespace lpvlab::cli
