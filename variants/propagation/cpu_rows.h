#pragma once
// What the row-vectorised CPU propagation kernels (standard_cpu.cpp, tetrahedral_cpu.cpp) share:
// the vector register type of an instruction set (on floats, doubles and dual numbers), its loads,
// stores and per-lane selection, and a call-free copy of a short row.

#include <cstring>

#include "framework/math/dual.h"

// The row kernels pass vector registers to always-inlined helpers (below): GCC's note that a 32-
// or 64-byte vector's calling convention differs without AVX concerns no real call. (For the rest
// of each kernel's translation unit, as where its includers set it before.)
#pragma GCC diagnostic ignored "-Wpsabi"

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

// On dual numbers (Dual, framework/math/dual.h: a value and kDualSlots derivatives) a register
// holds Bytes / 8 cells as a vector of their values and one of each derivative, so the kernel's
// text computes the derivatives of as many cells at a time as it computes doubles: the chain
// rule lane by lane. Loaded from and stored to the grid's Duals (a cell's value and derivatives
// together) by transposing.
template <int Lanes>
struct DualLanes {
  typedef double Values __attribute__((vector_size(8 * Lanes)));
  typedef long long Mask __attribute__((vector_size(8 * Lanes)));
  Values a, v[kDualSlots];

  DualLanes& operator+=(const DualLanes& o) {
    a += o.a;
    for (int j = 0; j < kDualSlots; ++j) v[j] += o.v[j];
    return *this;
  }
  friend DualLanes operator+(const DualLanes& x, const DualLanes& y) {
    DualLanes r = x;
    return r += y;
  }
  friend DualLanes operator*(const DualLanes& x, const DualLanes& y) {
    DualLanes r;
    r.a = x.a * y.a;
    for (int j = 0; j < kDualSlots; ++j) r.v[j] = x.v[j] * y.a + x.a * y.v[j];
    return r;
  }
  // By one Dual, the same for every lane (a table entry).
  friend DualLanes operator*(const DualLanes& x, const Dual& s) {
    DualLanes r;
    r.a = x.a * s.a;
    for (int j = 0; j < kDualSlots; ++j) r.v[j] = x.v[j] * s.a + x.a * s.v[j];
    return r;
  }
  friend Mask operator>(const DualLanes& x, const DualLanes& y) { return x.a > y.a; }
  friend Mask operator<(const DualLanes& x, const DualLanes& y) { return x.a < y.a; }
  friend Mask operator<=(const DualLanes& x, const Dual& s) { return x.a <= s.a; }
};

template <int Bytes>
struct RegisterOf<Dual, Bytes> {
  using type = DualLanes<Bytes / 8>;
  static constexpr int kLanes = Bytes / 8;
};

// A register's cells from memory and back (GCC vectors: an unaligned copy).
template <class V, class Real>
[[gnu::always_inline]] inline V loadRegister(const Real* from) {
  V v;
  std::memcpy(&v, from, sizeof(V));
  return v;
}
template <class V, class Real>
[[gnu::always_inline]] inline void storeRegister(Real* to, const V& v) {
  std::memcpy(to, &v, sizeof(V));
}
template <int Lanes>
[[gnu::always_inline]] inline void storeRegister(Dual* to, const DualLanes<Lanes>& v) {
  for (int i = 0; i < Lanes; ++i) {
    to[i].a = v.a[i];
    for (int j = 0; j < kDualSlots; ++j) to[i].v[j] = v.v[j][i];
  }
}
// Per lane, a where the mask is set, else b.
template <class M, class V>
[[gnu::always_inline]] inline V select(const M& mask, const V& a, const V& b) {
  return mask ? a : b;
}
template <int Lanes>
[[gnu::always_inline]] inline DualLanes<Lanes> select(const typename DualLanes<Lanes>::Mask& mask,
                                                      const DualLanes<Lanes>& a,
                                                      const DualLanes<Lanes>& b) {
  DualLanes<Lanes> r;
  r.a = mask ? a.a : b.a;
  for (int j = 0; j < kDualSlots; ++j) r.v[j] = mask ? a.v[j] : b.v[j];
  return r;
}

// loadRegister<DualLanes<L>> (a partial specialisation of a function is a struct's job).
template <class V>
struct DualLoad;
template <int Lanes>
struct DualLoad<DualLanes<Lanes>> {
  static DualLanes<Lanes> from(const Dual* p) {
    DualLanes<Lanes> r;
    for (int i = 0; i < Lanes; ++i) {
      r.a[i] = p[i].a;
      for (int j = 0; j < kDualSlots; ++j) r.v[j][i] = p[i].v[j];
    }
    return r;
  }
};
template <class V>
  requires requires { DualLoad<V>::from(nullptr); }
[[gnu::always_inline]] inline V loadRegister(const Dual* from) {
  return DualLoad<V>::from(from);
}

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
