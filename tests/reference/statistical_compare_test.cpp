// The statistical image comparison on synthetic Gaussian images with known means and variances:
// unbiased estimates are (almost) never rejected, biased ones are.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/reference/statistical_compare.h"

namespace lpvlab {
namespace {

constexpr int kSize = 64;

// An "estimate" of a known image: the truth plus Gaussian noise of the given standard deviation
// (varying per pixel), plus `shift` standard deviations of bias.
struct Synthetic {
  Image truth, estimate, variance;
};

Synthetic synthetic(double shift, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> uniform(0.5, 2.0);
  Synthetic s{Image(kSize, kSize, 3), Image(kSize, kSize, 3), Image(kSize, kSize, 3)};
  for (std::size_t i = 0; i < s.truth.pixels.size(); ++i) {
    const double mean = 10.0 * uniform(random), sigma = 0.1 * uniform(random);
    s.truth.pixels[i] = float(mean);
    s.variance.pixels[i] = float(sigma * sigma);
    s.estimate.pixels[i] = float(mean + sigma * (gaussian(random) + shift));
  }
  return s;
}

TEST(StatisticalCompare, CriticalValuesAreTheNormalQuantiles) {
  EXPECT_NEAR(twoSidedCriticalZ(0.05), 1.959963985, 1e-8);
  EXPECT_NEAR(twoSidedCriticalZ(0.01), 2.575829304, 1e-8);
  EXPECT_NEAR(twoSidedCriticalZ(1e-6), 4.891638475, 1e-8);
  EXPECT_THROW(twoSidedCriticalZ(0.0), Error);
}

TEST(StatisticalCompare, UnbiasedEstimatesAreNotRejected) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Synthetic s = synthetic(0.0, seed);
    const ComparisonResult result = compareToExact(s.estimate, s.variance, s.truth, 0.01);
    EXPECT_EQ(result.pixels, kSize * kSize);
    EXPECT_EQ(result.tests, kSize * kSize * 3);
    EXPECT_NEAR(result.expectedRejected, 0.01, 1e-4);  // Sidak: 1 - (1 - alpha)^(1/m) per test
    EXPECT_EQ(result.rejected, 0) << "seed " << seed << ", max |z| " << result.maxAbsZ;
    EXPECT_LT(result.maxAbsZ, result.threshold);
    // The mean of m independent standard normals has standard deviation 1 / sqrt(m).
    EXPECT_LT(std::abs(result.meanZ), 4.0 / std::sqrt(double(result.tests)));
  }
}

TEST(StatisticalCompare, BiasedEstimatesAreRejected) {
  const Synthetic s = synthetic(2.0, 7);  // every value 2 standard deviations high
  const ComparisonResult result = compareToExact(s.estimate, s.variance, s.truth, 0.01);
  EXPECT_GT(result.rejected, 0);
  EXPECT_NEAR(result.meanZ, 2.0, 0.1);
}

TEST(StatisticalCompare, TwoEstimatesPoolTheirVariances) {
  // Two independent unbiased estimates of one truth: their difference has the summed variance;
  // testing it against one variance alone would reject.
  const Synthetic a = synthetic(0.0, 11);
  Synthetic b = synthetic(0.0, 11);
  std::mt19937_64 random(12);
  std::normal_distribution<double> gaussian;
  for (std::size_t i = 0; i < b.estimate.pixels.size(); ++i)
    b.estimate.pixels[i] =
        float(b.truth.pixels[i] + std::sqrt(b.variance.pixels[i]) * gaussian(random));
  const ComparisonResult result = compareImages(a.estimate, a.variance, b.estimate, b.variance);
  EXPECT_EQ(result.rejected, 0) << "max |z| " << result.maxAbsZ;
  EXPECT_LT(std::abs(result.meanZ), 4.0 / std::sqrt(double(result.tests)));
}

TEST(StatisticalCompare, UnknownVariancesAreSkippedAndShapesMustMatch) {
  Synthetic s = synthetic(0.0, 3);
  for (int c = 0; c < 3; ++c) s.variance.at(5, 5, c) = INFINITY;
  const ComparisonResult result = compareToExact(s.estimate, s.variance, s.truth);
  EXPECT_EQ(result.pixels, kSize * kSize - 1);
  EXPECT_EQ(result.tests, (kSize * kSize - 1) * 3);
  EXPECT_THROW(compareToExact(s.estimate, s.variance, Image(kSize, kSize, 1)), Error);
}

TEST(StatisticalCompare, ANoiseFreeDifferenceBeyondRoundingIsRejected) {
  Image exact(1, 1, 1, 1.0f), variance(1, 1, 1, 0.0f);
  EXPECT_EQ(compareToExact(Image(1, 1, 1, 1.0f + 1e-7f), variance, exact).rejected, 0);
  EXPECT_EQ(compareToExact(Image(1, 1, 1, 1.001f), variance, exact).rejected, 1);
}

}  // namespace
}  // namespace lpvlab
