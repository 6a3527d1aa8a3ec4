#pragma once
// Reading an experiment file as one table: its `extends` chain and `include` files merged
// (docs/experiments.md).
//
//   extends = "base.toml"   at the top of an experiment file: the base (itself possibly extending
//                           another) is loaded and this file's tables are merged over it: a key in
//                           the child replaces the base's, sub-tables merge, arrays (of tables,
//                           e.g. [[lights]]) replace whole. A relative scene.file stays relative to
//                           the file that wrote it. A cycle is an error naming the files.
//   include = ["a.toml"]    parameter files (relative to this file; e.g. a fit's fitted.toml),
//                           merged like `extends` in order over the base, and under this file's
//                           own keys.

#include <toml++/toml.h>

#include <string>

namespace lpvlab {

// Reads an experiment file with its `extends` chain resolved and merged; the result has no
// `extends` key. Relative scene.file values of base files are made absolute.
toml::table readExperimentTable(const std::string& path);

// Merges `over` into `base` (sub-tables recursively; anything else replaces).
void mergeTables(toml::table& base, const toml::table& over);

// Makes the relative scene file references of `table` (read from `file`) absolute, so that they
// keep meaning the same files wherever the table is written or merged: scene.file and every
// particles[i].model ("builtin:" and "shared:" references stay as they are).
void absolutizeSceneFile(toml::table& table, const std::string& file);

}  // namespace lpvlab
