#pragma once
// Checking a sweep before it runs: every configuration loaded as `lpvlab run` would load it.

#include <toml++/toml.h>

#include <string>
#include <vector>

#include "framework/experiment/sweep_expansion.h"

namespace lpvlab {

// Loads every configuration of `root` (read from `file`, -s overrides applied) as `lpvlab run`
// would, each scene once, so that a swept key that does not exist or a swept value out of range
// is an Error naming `file`, its [sweep] table and the configuration, before anything is written.
// Returns, per configuration, the cache key of the reference it compares with ("" for none).
std::vector<std::string> checkConfigurations(const toml::table& root, const std::string& file,
                                             const std::vector<SweepConfiguration>& configurations);

}  // namespace lpvlab
