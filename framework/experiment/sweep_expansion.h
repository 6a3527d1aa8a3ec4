#pragma once
// A parameter sweep's configurations (docs/experiments.md):
//
//   [sweep]                 product = { "a.b" = [..], ... }   Cartesian product
//                           zip     = { "c.d" = [..], ... }   lists of equal length, together
//                           Both: every zip entry times every product entry. Each configuration
//                           is a list of overrides "key=value" applied like `-s key=value`, so
//                           unknown keys are errors of loadExperiment as usual.
//
// A sweep's outputs live in one directory DIR: DIR/configs/<id>.toml (the resolved configuration
// of each), DIR/<id>/ (its run, as `lpvlab run` writes it), DIR/sweep.json (the expansion and the
// sweep's hash), DIR/summary.csv (sweep_summary.h). Checking every configuration before a sweep
// runs: sweep_check.h.

#include <toml++/toml.h>

#include <string>
#include <utility>
#include <vector>

namespace lpvlab {

struct SweepConfiguration {
  std::string id;                       // short hash of the resolved configuration: every value
                                        // it runs with, swept or not (stable across runs)
  std::string name;                     // readable: "iterations=4,resolution=32" ("base": none)
  std::vector<std::string> overrides;   // "propagation.iterations=4" (TOML value text)
  std::vector<std::pair<std::string, std::string>> values;  // swept key -> value as text
};

// The configurations of `file`'s [sweep] table (one with no overrides when it has none); more
// than 100000 is an Error.
// `extraOverrides` (command-line -s) are applied before expansion and are part of every
// configuration's overrides (first), hence of its id. Throws an Error naming the file and key.
std::vector<SweepConfiguration> expandSweep(const std::string& file,
                                            const std::vector<std::string>& extraOverrides = {});
std::vector<SweepConfiguration> expandSweep(const toml::table& root, const std::string& file,
                                            const std::vector<std::string>& extraOverrides = {});

// Checks `root`'s [sweep] table as expandSweep does (its lists, a key swept twice, more than
// 100000 configurations) without expanding it; returns the number of configurations.
std::size_t checkSweep(const toml::table& root, const std::string& file);

// The swept keys, in column order (sorted, unique).
std::vector<std::string> sweptKeys(const toml::table& root, const std::string& file);

// The resolved TOML text of one configuration of `file` (extends merged, [sweep] removed,
// overrides applied, relative scene.file made absolute): a file `lpvlab run` reads on its own.
std::string configurationToml(const std::string& file, const SweepConfiguration& configuration);
// The same from `root`, the file's table as read (extends merged; -s overrides may be applied:
// applying the configuration's overrides again changes nothing), so a sweep reads its file once.
std::string configurationToml(const toml::table& root, const std::string& file,
                              const SweepConfiguration& configuration);

// The identity of a whole sweep (16 hex digits): the hash of `root` (read from `file` with its
// extends and includes merged and the -s overrides applied, [sweep] included). A sweep directory
// records it in sweep.json; only the same sweep resumes there.
std::string sweepHash(const toml::table& root, const std::string& file);

// The value of a TOML node as TOML text ("4", "\"standard\"", "[1, 2]").
std::string tomlValueText(const toml::node& node);

}  // namespace lpvlab
