#include "framework/core/cpu_features.h"

#include "framework/core/cpu_dispatch.h"

namespace lpvlab {

// Each function calls __builtin_cpu_init first: it may run before static constructors (from
// another static initialiser), and a second call is harmless.

bool cpuHasSse42() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("sse4.2");
}

bool cpuHasAvx() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx");
}

// GCC's own names for the psABI levels test exactly what its arch=x86-64-v3 / -v4 targets use.
// Clang 14 (the checked build, scripts/checked-build.sh) knows neither name, nor F16C, LZCNT and
// MOVBE: it tests the level's defining features, which no CPU has without those three.
bool cpuHasX86_64_v3() {
  __builtin_cpu_init();
#if defined(__clang__)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
         __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
#else
  return __builtin_cpu_supports("x86-64-v3");
#endif
}

bool cpuHasX86_64_v4() {
  __builtin_cpu_init();
#if defined(__clang__)
  return cpuHasX86_64_v3() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
         __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") &&
         __builtin_cpu_supports("avx512vl");
#else
  return __builtin_cpu_supports("x86-64-v4");
#endif
}

CpuKernelLevel widestCpuKernelLevel() {
  static const CpuKernelLevel widest = cpuHasX86_64_v4()   ? CpuKernelLevel::X86_64_V4
                                       : cpuHasX86_64_v3() ? CpuKernelLevel::X86_64_V3
                                                           : CpuKernelLevel::X86_64;
  return widest;
}

CpuKernelLevel pixelKernelLevel() {
  return widestCpuKernelLevel() == CpuKernelLevel::X86_64 ? CpuKernelLevel::X86_64
                                                          : CpuKernelLevel::X86_64_V3;
}

std::vector<CpuKernelLevel> cpuKernelLevelsThisCpuRuns() {
  std::vector<CpuKernelLevel> levels = {CpuKernelLevel::X86_64};
  if (cpuHasX86_64_v3()) levels.push_back(CpuKernelLevel::X86_64_V3);
  if (cpuHasX86_64_v4()) levels.push_back(CpuKernelLevel::X86_64_V4);
  return levels;
}

const char* cpuKernelLevelName(CpuKernelLevel level) {
  switch (level) {
    case CpuKernelLevel::X86_64_V4: return "x86-64-v4";
    case CpuKernelLevel::X86_64_V3: return "x86-64-v3";
    case CpuKernelLevel::X86_64: break;
  }
  return "x86-64";
}

}  // namespace lpvlab
