#include "framework/metrics/relative_difference.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "framework/metrics/mask.h"

namespace lpvlab {

nlohmann::json RelativeDifference::toJson() const {
  return {{"mean", mean}, {"p99", p99}, {"max", max}, {"epsilon", epsilon}, {"values", values}};
}

RelativeDifference relativeDifference(const Image& test, const Image& reference, const Image* mask) {
  const PixelMask covered = checkInputs("relativeDifference", test, reference, mask);
  const std::size_t pixels = std::size_t(test.width) * test.height;
  double sumReference = 0.0;
  std::int64_t values = 0;
  for (std::size_t p = 0; p < pixels; ++p)
    if (covered.covers(p))
      for (int c = 0; c < 3; ++c) sumReference += std::abs(double(reference.pixels[p * 3 + c])), ++values;
  RelativeDifference result;
  result.values = values;
  result.epsilon = 1e-3 * sumReference / double(values);
  std::vector<double> d;
  d.reserve(std::size_t(values));
  for (std::size_t p = 0; p < pixels; ++p) {
    if (!covered.covers(p)) continue;
    for (int c = 0; c < 3; ++c) {
      // All-black reference: epsilon is 0, and a difference counts as 1 (wholly different).
      d.push_back(relativeDifferenceOf(test.pixels[p * 3 + c], reference.pixels[p * 3 + c], result.epsilon));
    }
  }
  double sum = 0.0;
  for (double v : d) sum += v;
  result.mean = sum / double(d.size());
  // Nearest rank: the smallest value at or above which 1% of the values lie.
  const std::size_t rank = std::size_t(std::ceil(0.99 * double(d.size()))) - 1;
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(rank), d.end());
  result.p99 = d[rank];
  result.max = *std::max_element(d.begin(), d.end());
  return result;
}

}  // namespace lpvlab
