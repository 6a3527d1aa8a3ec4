#include "framework/gpubench/gpu_bench_inputs.h"

namespace lpvlab {
namespace {

// SplitMix64 (Steele, Lea and Flood 2014): a full-period hash of a 64-bit counter.
std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

std::vector<float> benchValues(std::size_t n, std::uint64_t stream, float low, float high) {
  std::vector<float> values(n);
  const std::uint64_t base = splitMix64(stream);
  for (std::size_t i = 0; i < n; ++i) {
    // The top 24 bits: a float in [0, 1) with every value exact.
    const double unit = double(splitMix64(base + i) >> 40) / double(1u << 24);
    values[i] = float(low + (high - low) * unit);
  }
  return values;
}

double benchChecksum(const std::vector<float>& values) {
  double sum = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i)
    sum += double(values[i]) * (1.0 + double(i % 13) / 13.0);
  return sum;
}

}  // namespace lpvlab
