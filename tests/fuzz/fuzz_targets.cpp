#include "fuzz/fuzz_targets.h"

namespace lpvlab::fuzz {

const std::vector<Target>& targets() {
  // The shipped experiments seed the TOML targets; tests/fuzz/seeds holds the rest.
  static const std::vector<Target> all = {
      {"experiment_file", experimentFile, {"experiments"}},
      {"fit_file", fitFile, {"experiments"}},
      {"overrides", overrides, {"tests/fuzz/seeds/overrides"}},
      {"reference_state", referenceState, {"tests/fuzz/seeds/reference_state"}},
      {"fit_progress", fitProgress, {"tests/fuzz/seeds/fit_progress"}},
      {"sweep_manifests", sweepManifests, {"tests/fuzz/seeds/sweep_manifests"}},
      {"scene_file", sceneFile, {"tests/fuzz/seeds/scene_file"}}};
  return all;
}

}  // namespace lpvlab::fuzz
