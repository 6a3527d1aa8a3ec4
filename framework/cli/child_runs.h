#pragma once
// Runs of `lpvlab run` in child processes, each with its own GL context, as `lpvlab sweep` and
// `lpvlab tune` run their configurations: `jobs` at a time, each into a fresh directory (an
// interrupted run's is removed and redone), with progress, stdout and stderr in its error.log.
// A run is finished when its directory holds a manifest.json (written last).

#include <filesystem>
#include <string>
#include <vector>

namespace lpvlab::cli {

struct ChildRun {
  std::string config;               // the resolved experiment file it runs
  std::filesystem::path directory;  // its --out
  std::string label;                // for messages: "<id> (<name>)"
};

// Runs every one of `runs` with the executable `exe`; returns the indices of those that failed
// (each named on stderr with its error.log's last line). `what` labels the progress bar.
std::vector<std::size_t> runChildren(const std::string& exe, const std::vector<ChildRun>& runs,
                                     int jobs, const std::string& what);

}  // namespace lpvlab::cli
