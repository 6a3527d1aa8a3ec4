#pragma once
// The benchmark's inputs and checksums, the same on every machine and standard library: each value
// is a hash of its index and stream (SplitMix64), not a <random> distribution, whose values differ
// between implementations. A checksum weights each value by its index, so that values swapped
// between cells change it:
//
//   checksum(v) = sum_i v_i (1 + (i mod 13) / 13),   in double.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lpvlab {

// n values uniform in [low, high] from stream `stream`.
std::vector<float> benchValues(std::size_t n, std::uint64_t stream, float low, float high);

double benchChecksum(const std::vector<float>& values);

// The checksum of a GL buffer's floats: a DualBuffer or a gl::Buffer (size() in bytes, download()).
template <class Buffer>
double benchChecksumOf(const Buffer& buffer) {
  std::vector<float> values(buffer.size() / sizeof(float));
  buffer.download(values.data(), values.size() * sizeof(float));
  return benchChecksum(values);
}

}  // namespace lpvlab
