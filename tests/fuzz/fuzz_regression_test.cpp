// Every input under tests/fuzz/regressions/<target>/ (each one made a fuzzer fail once) and every
// seed of the target replayed through it in every build: it must return or throw lpvlab::Error,
// nothing else. (The sanitizer build replays them under AddressSanitizer and UBSan too.)

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "framework/core/error.h"
#include "fuzz/fuzz_targets.h"

namespace lpvlab::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> filesIn(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) files.push_back(e.path());
  return files;
}

std::vector<fs::path> inputsOf(const Target& target) {
  const fs::path source(LPVLAB_SOURCE_DIR);
  std::vector<fs::path> inputs = filesIn(source / "tests" / "fuzz" / "regressions" / target.name);
  for (const std::string& seeds : target.seeds) {
    const std::vector<fs::path> more = filesIn(source / seeds);
    inputs.insert(inputs.end(), more.begin(), more.end());
  }
  return inputs;
}

TEST(FuzzRegressions, EveryTargetHasSeeds) {
  for (const Target& t : targets())
    for (const std::string& seeds : t.seeds)
      EXPECT_FALSE(filesIn(fs::path(LPVLAB_SOURCE_DIR) / seeds).empty()) << t.name << ": " << seeds;
}

TEST(FuzzRegressions, EveryKeptInputGivesAResultOrAnError) {
  int replayed = 0;
  for (const Target& t : targets()) {
    for (const fs::path& input : inputsOf(t)) {
      std::ifstream in(input, std::ios::binary);
      const std::vector<char> bytes{std::istreambuf_iterator<char>(in),
                                    std::istreambuf_iterator<char>()};
      try {
        t.run(reinterpret_cast<Bytes>(bytes.data()), bytes.size());
      } catch (const std::exception& e) {
        ADD_FAILURE() << input << ": " << t.name << " threw a " << typeid(e).name()
                      << " instead of an lpvlab::Error: " << e.what();
      }
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0);
}

}  // namespace
}  // namespace lpvlab::fuzz
