#pragma once
// What this x86-64 CPU can run, at the levels lpvlab picks code for at run time: Embree's
// instruction sets (framework/reference/embree_device.h) and the CPU kernels' compiled versions
// (variants/*/*_cpu.cpp). One place for the feature tests, so "AVX-512" means the same subset
// everywhere.

#include <string>
#include <vector>

namespace lpvlab {

bool cpuHasSse42();
bool cpuHasAvx();
// x86-64-v3: AVX2, FMA, BMI1/2, F16C, LZCNT, MOVBE (Haswell, Zen 1 on).
bool cpuHasX86_64_v3();
// x86-64-v4: AVX-512 F, CD, DQ, BW, VL (Skylake-server, Zen 4 on): what Embree's AVX-512
// kernels and GCC's x86-64-v4 target need.
bool cpuHasX86_64_v4();

// The names among `names` (instruction sets, narrowest first) for which runs(name) holds, in order.
template <class Runs>
std::vector<std::string> namesThisCpuRuns(const std::vector<std::string>& names, Runs runs) {
  std::vector<std::string> supported;
  for (const std::string& name : names)
    if (runs(name)) supported.push_back(name);
  return supported;
}

}  // namespace lpvlab
