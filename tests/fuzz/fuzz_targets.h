#pragma once
// The fuzzed entry points: everything lpvlab parses itself. Each takes arbitrary bytes; returning
// or throwing lpvlab::Error (one clear message) is correct, anything else is a bug: another
// exception type, a crash, a sanitizer report, a hang or an allocation the input did not justify.
// libfuzzer/entry.cpp turns one into a libFuzzer target (LPVLAB_FUZZ builds); fuzz_regression_test
// replays every input under regressions/<name>/ through it in every build.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lpvlab::fuzz {

using Bytes = const std::uint8_t*;

// An experiment file (with `extends`/`include` of the shipped experiments, [sweep]): read, every
// configuration expanded and loaded as `lpvlab sweep` checks them.
void experimentFile(Bytes data, std::size_t size);
// An experiment file with a [fit] table, read as `lpvlab fit` reads it.
void fitFile(Bytes data, std::size_t size);
// `-s key=value` overrides, one per line, applied to the built-in default and loaded.
void overrides(Bytes data, std::size_t size);
// A reference cache's state.bin.
void referenceState(Bytes data, std::size_t size);
// A fit's fit.progress.json.
void fitProgress(Bytes data, std::size_t size);
// A sweep directory's sweep.json and one run's manifest.json (separated by a line "===="), read
// back by `lpvlab summary`.
void sweepManifests(Bytes data, std::size_t size);
// A scene file through Assimp and lpvlab's conversion: the first byte picks OBJ (even) or glTF.
void sceneFile(Bytes data, std::size_t size);

struct Target {
  std::string name;  // the fuzzer's name (fuzz_<name>) and its folder under regressions/
  void (*run)(Bytes, std::size_t);
  std::vector<std::string> seeds;  // seed folders, relative to the source tree
};
const std::vector<Target>& targets();

}  // namespace lpvlab::fuzz
