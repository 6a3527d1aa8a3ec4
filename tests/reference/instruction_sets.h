#pragma once
// Runs a path tracer test suite once per instruction set Embree can be limited to (sse4.2, avx,
// avx2, avx512), so a machine with AVX-512 also checks the AVX2 and SSE4.2 kernels that other
// machines run. An instruction set this CPU lacks is skipped, and the skip says so.
//
// Under the sanitizers (the checked build) "avx" is skipped too: lpvlab's code is the same for
// every set and depends only on the query width, which avx shares with avx2 (8), so the checked
// build runs widths 4 (sse4.2), 8 (avx2) and 16 (avx512) once each, not avx's repeat of the
// -O0 path tracer (about 400 s of its time). The main build runs every set.
//
//   class Furnace : public testing::PerInstructionSet {};
//   TEST_P(Furnace, ...) { PathTracer tracer(..., tracerSettings()); ... }
//   LPVLAB_PER_INSTRUCTION_SET(Furnace);

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "framework/reference/embree_device.h"
#include "framework/reference/path_tracer.h"

namespace lpvlab::testing {

inline bool cpuRuns(const std::string& isa) {
  const std::vector<std::string> supported = supportedInstructionSets();
  return std::find(supported.begin(), supported.end(), isa) != supported.end();
}

class PerInstructionSet : public ::testing::TestWithParam<std::string> {
protected:
  void SetUp() override {
    if (!cpuRuns(GetParam())) GTEST_SKIP() << "this CPU lacks " << GetParam();
#ifdef LPVLAB_SANITIZED
    if (GetParam() == "avx")
      GTEST_SKIP() << "under the sanitizers avx repeats avx2's query width (the main build runs it)";
#endif
  }
  const std::string& isa() const { return GetParam(); }
  // Default settings on this test's instruction set, at its native query width.
  TracerSettings tracerSettings() const {
    TracerSettings settings;
    settings.engine.isa = GetParam();
    return settings;
  }
};

// Test names cannot hold '.': "sse4.2" is named sse4_2.
inline std::string instructionSetName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '.', '_');
  return name;
}

}  // namespace lpvlab::testing

#define LPVLAB_PER_INSTRUCTION_SET(Suite)                                          \
  INSTANTIATE_TEST_SUITE_P(Isa, Suite,                                             \
                           ::testing::ValuesIn(::lpvlab::embreeInstructionSets()), \
                           ::lpvlab::testing::instructionSetName)
