#pragma once
// Counter-based random numbers for the path tracer: sample s of pixel p gets its own stream, a
// SplitMix64 sequence started from a hash of (seed, p, s), or the Owen-scrambled Sobol points of
// (seed, p) at index s (SampleSequence). Nothing depends on which thread
// traces the sample or on what was traced before it, which is what makes images bit-identical
// for any thread count and lets an accumulator resume where it stopped.

#include <cstdint>
#include <string>
#include <vector>

#include "framework/reference/mix64.h"
#include "framework/reference/owen_sobol.h"

namespace lpvlab {

// How a path's random numbers are made ([reference] sampler).
//   Independent  every number independent: SplitMix64 from a hash of (seed, pixel, sample)
//   Sobol        Owen-scrambled Sobol points padded in pairs of dimensions (owen_sobol.h): a
//                pixel's samples are stratified in each pair of dimensions (the pixel position,
//                then each bounce's light and direction choices), so they converge faster;
//                samples of a pixel are no longer independent of each other
enum class SampleSequence { Independent, Sobol };

inline const char* samplerName(SampleSequence sequence) {
  return sequence == SampleSequence::Sobol ? "sobol" : "independent";
}

// The `sampler` keys' choices, and the sequence a checked choice names.
inline const std::vector<std::string>& samplerNames() {
  static const std::vector<std::string> names = {"independent", "sobol"};
  return names;
}
inline SampleSequence samplerFromName(const std::string& name) {
  return name == "sobol" ? SampleSequence::Sobol : SampleSequence::Independent;
}

class SampleRandom {
public:
  SampleRandom() = default;  // a placeholder (for arrays): assign a keyed stream before drawing
  SampleRandom(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample,
               SampleSequence sequence = SampleSequence::Independent)
      : key_(mix64(mix64(seed) + pixel)),
        state_(mix64(key_ + sample)),
        sample_(std::uint32_t(sample)),
        sobol_(sequence == SampleSequence::Sobol) {}

  // Uniform in [0, 1): the top 24 bits of the next output, so every value is an exact float.
  // The n-th call of a sample is its dimension n.
  float uniform() {
    if (sobol_) return sobolUniform();
    state_ += 0x9e3779b97f4a7c15ull;  // SplitMix64's increment (the golden ratio in 64 bits)
    return float(mix64(state_) >> 40) * 0x1p-24f;
  }

private:
  float sobolUniform() {
    if (dimension_ % 2 == 0) {
      const owen_sobol::Pair pair = owen_sobol::pairAt(key_, dimension_ / 2, sample_);
      ++dimension_;
      second_ = pair.y;
      return float(pair.x >> 8) * 0x1p-24f;
    }
    ++dimension_;
    return float(second_ >> 8) * 0x1p-24f;
  }

  std::uint64_t key_ = 0;      // the stream of (seed, pixel); Sobol: its scrambles' key
  std::uint64_t state_ = 0;    // independent: SplitMix64's state, from key_ and the sample
  std::uint32_t sample_ = 0;   // Sobol: the sample index (its first 2^32 samples)
  std::uint32_t dimension_ = 0;
  std::uint32_t second_ = 0;   // Sobol: the pair's second value, returned by the next call
  bool sobol_ = false;
};

}  // namespace lpvlab
