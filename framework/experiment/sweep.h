#pragma once
// Experiment inheritance and parameter sweeps (see docs/experiments.md).
//
//   extends = "base.toml"   at the top of an experiment file: the base (itself possibly extending
//                           another) is loaded and this file's tables are merged over it: a key in
//                           the child replaces the base's, sub-tables merge, arrays (of tables,
//                           e.g. [[lights]]) replace whole. A relative scene.file stays relative to
//                           the file that wrote it. A cycle is an error naming the files.
//   include = ["a.toml"]    parameter files (relative to this file; e.g. a fit's fitted.toml),
//                           merged like `extends` in order over the base, and under this file's
//                           own keys.
//   [sweep]                 product = { "a.b" = [..], ... }   Cartesian product
//                           zip     = { "c.d" = [..], ... }   lists of equal length, together
//                           Both: every zip entry times every product entry. Each configuration
//                           is a list of overrides "key=value" applied like `-s key=value`, so
//                           unknown keys are errors of loadExperiment as usual.
//
// A sweep's outputs live in one directory DIR: DIR/configs/<id>.toml (the resolved configuration
// of each), DIR/<id>/ (its run, as `lpvlab run` writes it), DIR/sweep.json (the expansion),
// DIR/summary.csv (rebuilt from the run directories' manifests by writeSweepSummary).

#include <toml++/toml.h>

#include <string>
#include <utility>
#include <vector>

#include "framework/experiment/experiment.h"

namespace lpvlab {

struct SweepConfiguration {
  std::string id;                       // short hash of the resolved configuration: every value
                                        // it runs with, swept or not (stable across runs)
  std::string name;                     // readable: "iterations=4,resolution=32" ("base": none)
  std::vector<std::string> overrides;   // "propagation.iterations=4" (TOML value text)
  std::vector<std::pair<std::string, std::string>> values;  // swept key -> value as text
};

// Reads an experiment file with its `extends` chain resolved and merged; the result has no
// `extends` key. Relative scene.file values of base files are made absolute.
toml::table readExperimentTable(const std::string& path);

// Merges `over` into `base` (sub-tables recursively; anything else replaces).
void mergeTables(toml::table& base, const toml::table& over);

// The configurations of `file`'s [sweep] table (one with no overrides when it has none); more
// than 100000 is an Error.
// `extraOverrides` (command-line -s) are applied before expansion and are part of every
// configuration's overrides (first), hence of its id. Throws an Error naming the file and key.
std::vector<SweepConfiguration> expandSweep(const std::string& file,
                                            const std::vector<std::string>& extraOverrides = {});
std::vector<SweepConfiguration> expandSweep(const toml::table& root, const std::string& file,
                                            const std::vector<std::string>& extraOverrides = {});

// Loads every configuration of `root` (read from `file`, -s overrides applied) as `lpvlab run`
// would, each scene once, so that a swept key that does not exist or a swept value out of range
// is an Error naming `file`, its [sweep] table and the configuration, before anything is written.
// Returns, per configuration, the cache key of the reference it compares with ("" for none).
std::vector<std::string> checkConfigurations(const toml::table& root, const std::string& file,
                                             const std::vector<SweepConfiguration>& configurations);

// The swept keys, in column order (sorted, unique).
std::vector<std::string> sweptKeys(const toml::table& root, const std::string& file);

// The resolved TOML text of one configuration of `file` (extends merged, [sweep] removed,
// overrides applied, relative scene.file made absolute): a file `lpvlab run` reads on its own.
std::string configurationToml(const std::string& file, const SweepConfiguration& configuration);

// The identity of a whole sweep (16 hex digits): the hash of `root` (read from `file` with its
// extends and includes merged and the -s overrides applied, [sweep] included). A sweep directory
// records it in sweep.json; only the same sweep resumes there.
std::string sweepHash(const toml::table& root, const std::string& file);

// The value of a TOML node as TOML text ("4", "\"standard\"", "[1, 2]").
std::string tomlValueText(const toml::node& node);

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
