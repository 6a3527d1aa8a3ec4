#pragma once
// Owen-scrambled Sobol points, padded in pairs of dimensions: the low-discrepancy sequence of the
// path tracer's `sampler = "sobol"` (random.h). Burley, "Practical Hash-based Owen Scrambling",
// JCGT 9(4), 2020:
//   - the first two Sobol dimensions (a (0,2)-sequence: every aligned block of 2^m points is a
//     (0,m,2)-net, stratified in every elementary interval of area 2^-m);
//   - each dimension Owen-scrambled (nested uniform scrambling) by a hash: the Laine-Karras
//     permutation of the bit-reversed value, which flips each bit depending only on the bits
//     above it, with its own seed per dimension;
//   - each pair of dimensions (2k, 2k+1) reads the sequence at the sample index shuffled by the
//     same scramble with a seed of its own, so pairs are not correlated with each other. The
//     shuffle maps the first 2^m indices onto an aligned block of 2^m (its high bits are flipped
//     by the seed alone), so any power-of-two prefix of a pixel's samples is still a net.
// Everything is a pure function of (seed, pixel, sample index, dimension): no state between
// samples, as the independent sampler.

#include <cstdint>

#include "framework/reference/mix64.h"

namespace lpvlab::owen_sobol {

inline std::uint32_t reverseBits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// Laine and Karras's hash (Burley's constants): each output bit depends on the input bits below
// it alone (additions and multiplications carry upwards), and it is a bijection.
inline std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// Nested uniform (Owen) scrambling of a 32-bit fixed-point value in [0, 1): bit k flipped by a
// hash of the bits above it.
inline std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
  return reverseBits(laineKarras(reverseBits(x), seed));
}

// Sobol dimension 0: the van der Corput sequence (the index's bits reversed).
inline std::uint32_t sobolDimension0(std::uint32_t index) { return reverseBits(index); }

// Sobol dimension 1 (primitive polynomial x + 1): the direction numbers are Pascal's triangle
// mod 2, v_{k+1} = v_k ^ (v_k >> 1) from v_0 = 2^31.
inline std::uint32_t sobolDimension1(std::uint32_t index) {
  std::uint32_t result = 0;
  for (std::uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) result ^= v;
  return result;
}

// A 32-bit value from a 64-bit key (mix64, folded).
inline std::uint32_t seedOf(std::uint64_t key) {
  const std::uint64_t z = mix64(key);
  return std::uint32_t(z ^ (z >> 32));
}

// Dimensions (2 pair, 2 pair + 1) of sample `index` of the stream keyed `key` (a hash of seed
// and pixel), as 32-bit fixed point in [0, 1).
struct Pair {
  std::uint32_t x, y;
};

inline Pair pairAt(std::uint64_t key, std::uint32_t pair, std::uint32_t index) {
  const std::uint64_t pairKey = key + 0x9e3779b97f4a7c15ull * (std::uint64_t(pair) + 1);
  const std::uint32_t shuffled = nestedUniformScramble(index, seedOf(pairKey));
  return {nestedUniformScramble(sobolDimension0(shuffled), seedOf(pairKey ^ 0x5851f42d4c957f2dull)),
          nestedUniformScramble(sobolDimension1(shuffled), seedOf(pairKey ^ 0x14057b7ef767814full))};
}

}  // namespace lpvlab::owen_sobol
