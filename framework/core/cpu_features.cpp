#include "framework/core/cpu_features.h"

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
bool cpuHasX86_64_v3() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v3");
}

bool cpuHasX86_64_v4() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v4");
}

}  // namespace lpvlab
