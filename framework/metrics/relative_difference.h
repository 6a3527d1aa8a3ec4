#pragma once
// How far one rendering of a configuration is from another of the same configuration (the GL
// kernels against the CPU kernels, one GPU against another): per value (covered pixel and RGB
// channel) the relative difference
//
//   d = |t - r| / (|r| + epsilon),   epsilon = 1e-3 * mean |r| over the covered values,
//
// summarised by its mean, 99th percentile (nearest rank) and maximum. The epsilon, a thousandth
// of the image's mean, keeps the near-black values (a shadow's, a dark corner's) from turning a
// rounding difference into an infinite relative one, and makes the figures independent of the
// radiance units. Two all-black images (mean 0) differ by 0 where they agree, and by 1 wherever
// the test is not 0.

#include <cstdint>

#include <nlohmann/json.hpp>

#include "framework/io/image.h"

namespace lpvlab {

struct RelativeDifference {
  double mean = 0.0, p99 = 0.0, max = 0.0;
  double epsilon = 0.0;    // in the reference's units
  std::int64_t values = 0; // covered pixels x 3

  nlohmann::json toJson() const;  // {"mean", "p99", "max", "epsilon", "values"}
};

// One value's relative difference |t - r| / (|r| + epsilon); with epsilon 0 (an all-black
// reference) 1 where they differ, else 0.
inline double relativeDifferenceOf(double t, double r, double epsilon) {
  const double difference = t > r ? t - r : r - t;
  if (epsilon > 0.0) return difference / ((r < 0.0 ? -r : r) + epsilon);
  return difference > 0.0 ? 1.0 : 0.0;
}

// `test` against `reference` over the pixels `mask` covers (1-channel, 0 = background; none: all).
// Throws an Error as computeMetrics does for mismatched sizes, non-RGB images or NaN/Inf values.
RelativeDifference relativeDifference(const Image& test, const Image& reference,
                                      const Image* mask = nullptr);

}  // namespace lpvlab
