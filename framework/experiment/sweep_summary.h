#pragma once
// A sweep's summary.csv: one row per configuration and repeat (a sequence's: per frame), built
// from the run directories' manifests (docs/experiments.md lists the columns).

#include <string>
#include <utility>
#include <vector>

namespace lpvlab {

struct SummaryResult {
  int rows = 0;
  std::vector<std::string> complete;     // config ids with a manifest that gave rows
  std::vector<std::string> incomplete;   // configurations' run directories without a manifest
  std::vector<std::string> foreign;      // directories that are no configuration of sweep.json
  std::vector<std::pair<std::string, std::string>> dropped;  // id, why its manifest gave no row
};

// Rebuilds DIR/summary.csv from the manifests of the configurations DIR/sweep.json records
// (atomically), with their swept keys and names. Nothing else in DIR is read: another sweep's or
// run's directories are returned as foreign, configurations without a manifest as incomplete,
// manifests with no timed frame (no timing samples) as dropped with the reason.
SummaryResult writeSweepSummary(const std::string& dir);

}  // namespace lpvlab
