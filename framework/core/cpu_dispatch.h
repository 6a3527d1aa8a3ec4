#pragma once
// Runs a CPU kernel's inner loop compiled for one of x86-64, x86-64-v3 (AVX2, FMA) and x86-64-v4
// (AVX-512), chosen at run time among those this CPU has: one binary for every x86-64, the same
// source for every level (compiler vectorisation, as standard propagation's rows are compiled;
// variants/propagation/standard_cpu.cpp). The body is inlined whole into each version
// (gnu::flatten), so the shared GLSL functions it calls take that version's instruction set:
// floor is one instruction from SSE4.1 on, float multiply-adds fuse with FMA.
//
// Call it per unit of parallel work (a row of pixels), not around the parallel loop: the body
// must be an ordinary loop to inline.

#include <vector>

namespace lpvlab {

enum class CpuKernelLevel { X86_64, X86_64_V3, X86_64_V4 };

// The widest level this CPU runs (found once).
CpuKernelLevel widestCpuKernelLevel();
// What the per-pixel kernels (direct light, RSM injection, trilinear rendering) run unless told
// otherwise: the widest up to x86-64-v3. They are mostly scalar code with short vectors (a
// cell's N coefficients); AVX-512 brought them nothing measurable on a Zen 4 and its masked tails
// cost trilinear rendering at SH order 2 about 15% (bench_cpu_kernels, docs/benchmarks.md).
CpuKernelLevel pixelKernelLevel();
// Every level this CPU runs, narrowest first (tests compare them), and a level's name as
// standard propagation's `isa` spells it ("x86-64", "x86-64-v3", "x86-64-v4").
std::vector<CpuKernelLevel> cpuKernelLevelsThisCpuRuns();
const char* cpuKernelLevelName(CpuKernelLevel level);

namespace cpu_dispatch_detail {
template <class Body>
[[gnu::flatten]] void runX86_64(const Body& body) { body(); }
template <class Body>
[[gnu::flatten, gnu::target("arch=x86-64-v3")]] void runX86_64V3(const Body& body) { body(); }
template <class Body>
[[gnu::flatten, gnu::target("arch=x86-64-v4")]] void runX86_64V4(const Body& body) { body(); }
}  // namespace cpu_dispatch_detail

// The body compiled for `Level` alone: for bodies that differ per level (a register width),
// where runAtLevel would compile each of them for every level.
template <CpuKernelLevel Level, class Body>
void runAtFixedLevel(const Body& body) {
  if constexpr (Level == CpuKernelLevel::X86_64_V4)
    cpu_dispatch_detail::runX86_64V4(body);
  else if constexpr (Level == CpuKernelLevel::X86_64_V3)
    cpu_dispatch_detail::runX86_64V3(body);
  else
    cpu_dispatch_detail::runX86_64(body);
}

template <class Body>
void runAtLevel(CpuKernelLevel level, const Body& body) {
  switch (level) {
    case CpuKernelLevel::X86_64_V4: return cpu_dispatch_detail::runX86_64V4(body);
    case CpuKernelLevel::X86_64_V3: return cpu_dispatch_detail::runX86_64V3(body);
    case CpuKernelLevel::X86_64: return cpu_dispatch_detail::runX86_64(body);
  }
}

}  // namespace lpvlab
