#pragma once
// [tune.fit] (docs/tuning.md): after the search, the chosen configuration's constants fitted by
// `lpvlab fit` on the tuned views. The search draws constants at random; the fit (Levenberg-
// Marquardt through the frames, framework/fit/) finds the nearest optimum of its residual from
// there. The fit runs in a child process into DIR/fit/ (resumable as any fit: a tune started
// again after a kill goes on with it), from DIR/configs/fit.toml: the tune file's baseline with
// the chosen overrides, the last rung's reference, and [tune.fit] as its [fit] table.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/tune/tune_spec.h"

namespace lpvlab::cli {

struct TuneFit {
  std::vector<std::string> overrides;  // the chosen's, each fitted constant set to its fitted value
  nlohmann::json record;               // for tune.json: where, each constant before and after, converged
};

// Fits the constants of [tune.fit] (spec.fit) from the configuration `chosen` (its overrides;
// `runOverrides` are added, the last rung's reference and timing). A constant the images left
// undetermined keeps its chosen value. An Error where the fit cannot run or fails.
TuneFit fitChosenConstants(const TuneSpec& spec, const std::filesystem::path& dir,
                           const std::vector<std::string>& chosen, const std::vector<std::string>& runOverrides);

}  // namespace lpvlab::cli
