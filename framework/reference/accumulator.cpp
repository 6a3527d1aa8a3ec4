#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.h"
#include "framework/reference/path_tracer.h"

namespace lpvlab {

namespace {

constexpr double kLuminanceWeights[3] = {0.2126, 0.7152, 0.0722};  // Rec. 709

// Variance of the mean of n samples from their sum and sum of squares: the unbiased sample
// variance over n. Rounding can leave the difference slightly negative for constant samples.
double varianceOfMean(double sum, double sumSquares, std::int64_t n) {
  if (n < 2) return std::numeric_limits<double>::infinity();
  const double sampleVariance = std::max(0.0, (sumSquares - sum * sum / double(n)) / double(n - 1));
  return sampleVariance / double(n);
}

}  // namespace

Accumulator::Accumulator(int width, int height) : width(width), height(height) {
  if (width < 1 || height < 1)
    throw Error("accumulator: image size " + std::to_string(width) + "x" + std::to_string(height) +
                " must be at least 1x1");
  const std::size_t pixels = std::size_t(width) * height;
  sum.assign(pixels * kRadianceValues, 0.0);
  sumSquares.assign(pixels * kRadianceValues, 0.0);
  firstHit.assign(pixels * kFirstHitValues, 0.0);
}

std::vector<NamedImage> Accumulator::images() const {
  const std::size_t pixels = std::size_t(width) * height;
  const double perSample = samples > 0 ? 1.0 / double(samples) : 0.0;
  std::vector<NamedImage> means, variances;
  for (int aov = 0; aov < kRadianceAovs; ++aov) {
    Image mean(width, height, 3), variance(width, height, 3);
    for (std::size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = p * kRadianceValues + aov * 3 + c;
        mean.pixels[p * 3 + c] = float(sum[i] * perSample);
        variance.pixels[p * 3 + c] = float(varianceOfMean(sum[i], sumSquares[i], samples));
      }
    means.push_back({kRadianceNames[aov], std::move(mean)});
    variances.push_back({std::string(kRadianceNames[aov]) + "_variance", std::move(variance)});
  }
  // firstHit's values: albedo at 0, normal at 3, depth at 6.
  const struct {
    const char* name;
    int first, channels;
  } firstHitAovs[] = {{"albedo", 0, 3}, {"normal", 3, 3}, {"depth", 6, 1}};
  for (const auto& aov : firstHitAovs) {
    Image mean(width, height, aov.channels);
    for (std::size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < aov.channels; ++c)
        mean.pixels[p * aov.channels + c] =
            float(firstHit[p * kFirstHitValues + aov.first + c] * perSample);
    means.push_back({aov.name, std::move(mean)});
  }
  for (NamedImage& variance : variances) means.push_back(std::move(variance));
  return means;
}

double Accumulator::meanRelativeError(double epsilon) const {
  if (samples < 2) return std::numeric_limits<double>::infinity();
  constexpr int kCombined = 3;
  const std::size_t pixels = std::size_t(width) * height;
  double total = 0.0;
  std::size_t covered = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    if (!(firstHit[p * kFirstHitValues + 6] > 0.0)) continue;  // depth > 0: some sample hit
    double mean = 0.0, standardError = 0.0;
    for (int c = 0; c < 3; ++c) {
      const std::size_t i = p * kRadianceValues + kCombined * 3 + c;
      mean += kLuminanceWeights[c] * sum[i] / double(samples);
      standardError +=
          kLuminanceWeights[c] * std::sqrt(varianceOfMean(sum[i], sumSquares[i], samples));
    }
    total += standardError / std::max(mean, epsilon);
    ++covered;
  }
  return covered > 0 ? total / double(covered) : 0.0;
}

}  // namespace lpvlab
