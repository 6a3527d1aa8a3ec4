#pragma once
// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijection on 64 bits whose every output bit
// depends on every input bit. The path tracer's random streams (random.h) and the Sobol
// scrambles' seeds (owen_sobol.h) are hashed with it.

#include <cstdint>

namespace lpvlab {

inline std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace lpvlab
