#include "framework/reference/statistical_compare.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

void requireSameShape(const Image& a, const Image& b, const char* what) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw Error(std::string("statistical comparison: ") + what + " is " + std::to_string(b.width) +
                "x" + std::to_string(b.height) + "x" + std::to_string(b.channels) +
                ", the estimate " + std::to_string(a.width) + "x" + std::to_string(a.height) + "x" +
                std::to_string(a.channels));
}

}  // namespace

double twoSidedCriticalZ(double level) {
  if (!(level > 0.0 && level < 1.0))
    throw Error("statistical comparison: significance level must be in (0, 1)");
  // P(|Z| > z) = erfc(z / sqrt 2) falls monotonically in z: bisect (to double precision; the tail
  // below 1e-300 starts near z = 37).
  double low = 0.0, high = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    (std::erfc(mid / std::sqrt(2.0)) > level ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

ComparisonResult compareImages(const Image& a, const Image& varianceA, const Image& b,
                               const Image& varianceB, double familyAlpha, double relativeFloor) {
  requireSameShape(a, varianceA, "the first variance image");
  requireSameShape(a, b, "the second image");
  requireSameShape(a, varianceB, "the second variance image");
  if (!(familyAlpha > 0.0 && familyAlpha < 1.0))
    throw Error("statistical comparison: family-wise alpha must be in (0, 1)");

  ComparisonResult result;
  result.pixelMaxAbsZ = Image(a.width, a.height, 1);
  std::vector<double> z;
  z.reserve(a.pixels.size());
  for (std::size_t p = 0; p < a.pixels.size(); p += a.channels) {
    bool tested = false;
    for (int c = 0; c < a.channels; ++c) {
      const std::size_t i = p + c;
      const double variance = double(varianceA.pixels[i]) + double(varianceB.pixels[i]);
      if (!std::isfinite(variance)) continue;
      const double difference = double(a.pixels[i]) - double(b.pixels[i]);
      const double floor = relativeFloor * std::max(std::abs(a.pixels[i]), std::abs(b.pixels[i]));
      const double standardError = std::max(std::sqrt(variance), floor);
      // A difference with no uncertainty at all gets an infinite z.
      z.push_back(difference == 0.0 ? 0.0 : difference / standardError);
      float& pixelZ = result.pixelMaxAbsZ.pixels[p / std::size_t(a.channels)];
      pixelZ = std::max(pixelZ, float(std::abs(z.back())));
      tested = true;
    }
    result.pixels += tested;
  }
  result.tests = std::int64_t(z.size());
  if (result.tests == 0) return result;
  const double perTestLevel = -std::expm1(std::log1p(-familyAlpha) / double(result.tests));
  result.threshold = twoSidedCriticalZ(perTestLevel);
  result.expectedRejected = perTestLevel * double(result.tests);
  double total = 0.0;
  for (double value : z) {
    result.rejected += std::abs(value) > result.threshold;
    result.maxAbsZ = std::max(result.maxAbsZ, std::abs(value));
    total += value;
  }
  result.meanZ = total / double(result.tests);
  return result;
}

ComparisonResult compareToExact(const Image& estimate, const Image& variance, const Image& exact,
                                double familyAlpha, double relativeFloor) {
  return compareImages(estimate, variance, exact, Image(exact.width, exact.height, exact.channels),
                       familyAlpha, relativeFloor);
}

}  // namespace lpvlab
