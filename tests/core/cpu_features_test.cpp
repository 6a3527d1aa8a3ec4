// The CPU feature levels lpvlab dispatches on are nested (a CPU with a wider level has every
// narrower one, as the psABI levels and Intel's and AMD's parts have them), and this machine has
// at least SSE4.2, lpvlab's floor; namesThisCpuRuns keeps the order and filters by its predicate.

#include <gtest/gtest.h>

#include "framework/core/cpu_features.h"

namespace lpvlab {
namespace {

TEST(CpuFeatures, LevelsAreNestedAndSse42IsTheFloor) {
  EXPECT_TRUE(cpuHasSse42());
  // Each level implies the one below it (written as implications: no assertion under an if).
  EXPECT_TRUE(!cpuHasX86_64_v4() || cpuHasX86_64_v3());
  EXPECT_TRUE(!cpuHasX86_64_v3() || cpuHasAvx());
  EXPECT_TRUE(!cpuHasAvx() || cpuHasSse42());
}

TEST(CpuFeatures, NamesThisCpuRunsKeepsOrderAndFilters) {
  const std::vector<std::string> names = {"a", "bb", "c", "dd"};
  EXPECT_EQ(namesThisCpuRuns(names, [](const std::string& n) { return n.size() == 2; }),
            (std::vector<std::string>{"bb", "dd"}));
  EXPECT_TRUE(namesThisCpuRuns(names, [](const std::string&) { return false; }).empty());
}

}  // namespace
}  // namespace lpvlab
