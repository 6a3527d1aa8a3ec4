#pragma once
// What the row-vectorised CPU propagation kernels (standard_cpu.cpp, tetrahedral_cpu.cpp) share:
// the vector register type of an instruction set and a call-free copy of a short row.

#include <cstring>

namespace lpvlab::cpu_rows {

// Cells along x are computed a register at a time: a GCC vector (vector_size) of `Bytes`, the
// width of the instruction set's registers (16 SSE, 32 AVX2, 64 AVX-512), so every cell is
// computed with vector instructions. The kernels pad their rows to a multiple of 16 cells, a
// whole number of registers at every width, so no cell falls to a scalar remainder loop.
template <class Real, int Bytes>
struct RegisterOf {
  typedef Real type __attribute__((vector_size(Bytes)));
  static constexpr int kLanes = Bytes / int(sizeof(Real));
};

// Copies `count` values (a row of the grid, short) without a call: runs of 8 values as fixed-size
// copies the compiler inlines, the last run ending at `count` (overlapping the one before, which
// writes the same values again). A row of 32 cells per coefficient and neighbour direction made
// std::copy's memmove calls a tenth of standard propagation's time.
template <class Real>
[[gnu::always_inline]] inline void copyShortRun(const Real* from, Real* to, int count) {
  constexpr int kRun = 8;
  if (count < kRun) {
    for (int i = 0; i < count; ++i) to[i] = from[i];
    return;
  }
  for (int i = 0; i + kRun <= count; i += kRun) std::memcpy(to + i, from + i, kRun * sizeof(Real));
  std::memcpy(to + count - kRun, from + count - kRun, kRun * sizeof(Real));
}

}  // namespace lpvlab::cpu_rows
