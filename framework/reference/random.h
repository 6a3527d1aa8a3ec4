#pragma once
// Counter-based random numbers for the path tracer: sample s of pixel p gets its own stream, a
// SplitMix64 sequence started from a hash of (seed, p, s). Nothing depends on which thread
// traces the sample or on what was traced before it, which is what makes images bit-identical
// for any thread count and lets an accumulator resume where it stopped.

#include <cstdint>

namespace lpvlab {

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijection on 64 bits whose every output
// bit depends on every input bit.
inline std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class SampleRandom {
public:
  SampleRandom() = default;  // a placeholder (for arrays): assign a keyed stream before drawing
  SampleRandom(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample)
      : state_(mix64(mix64(mix64(seed) + pixel) + sample)) {}

  // Uniform in [0, 1): the top 24 bits of the next output, so every value is an exact float.
  float uniform() {
    state_ += 0x9e3779b97f4a7c15ull;  // SplitMix64's increment (the golden ratio in 64 bits)
    return float(mix64(state_) >> 40) * 0x1p-24f;
  }

private:
  std::uint64_t state_ = 0;
};

}  // namespace lpvlab
