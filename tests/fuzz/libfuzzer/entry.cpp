// libFuzzer's entry point (the fuzz_lpvlab executable of LPVLAB_FUZZ builds) for the targets of
// fuzz_targets.h:
//   fuzz_lpvlab -lpvlab_target=NAME [libFuzzer flags] [CORPUS...]   fuzz one target
//   fuzz_lpvlab -lpvlab_list                                         print the targets' names
// The target's seed folders are added after the corpus folders given; when none is given, new
// inputs go to ./fuzz-corpus-NAME (libFuzzer writes into the first folder, never a seed folder).
// run_fuzzers.sh runs every target in turn.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz/fuzz_targets.h"
#include "fuzz/fuzz_workspace.h"

namespace {

const lpvlab::fuzz::Target* target = nullptr;
std::vector<std::string> arguments;  // what argv points into after LLVMFuzzerInitialize
std::vector<char*> argvStorage;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const std::string targetFlag = "-lpvlab_target=";
  std::string name;
  bool corpusGiven = false, singleInputs = false;
  for (int i = 0; i < *argc; ++i) {
    const std::string a = (*argv)[i];
    if (a == "-lpvlab_list") {
      for (const lpvlab::fuzz::Target& t : lpvlab::fuzz::targets())
        std::printf("%s\n", t.name.c_str());
      std::exit(0);
    }
    if (a.rfind(targetFlag, 0) == 0) {  // ours: libFuzzer does not see it
      name = a.substr(targetFlag.size());
      continue;
    }
    arguments.push_back(a);
    if (i == 0 || a.rfind("-", 0) == 0) continue;
    if (std::filesystem::is_directory(a))
      corpusGiven = true;
    else
      singleInputs = true;  // replaying files (e.g. a crash): no corpus then
  }
  for (const lpvlab::fuzz::Target& t : lpvlab::fuzz::targets())
    if (t.name == name) target = &t;
  if (!target) {
    std::fprintf(stderr,
                 "fuzz_lpvlab: name a target with -lpvlab_target=NAME (-lpvlab_list lists them)\n");
    std::exit(2);
  }
  if (!singleInputs) {
    if (!corpusGiven) {
      const std::string corpus = "fuzz-corpus-" + name;
      std::filesystem::create_directories(corpus);
      arguments.push_back(corpus);
    }
    for (const std::string& seeds : target->seeds)
      arguments.push_back((std::filesystem::path(LPVLAB_SOURCE_DIR) / seeds).string());
  }
  for (std::string& a : arguments) argvStorage.push_back(a.data());
  argvStorage.push_back(nullptr);
  *argc = int(arguments.size());
  *argv = argvStorage.data();
  lpvlab::fuzz::FuzzWorkspace::instance();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  target->run(data, size);
  return 0;
}
