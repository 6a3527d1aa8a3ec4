// SSIM: closed forms for constant images, symmetry, and the range for opposite structure.

#include <cmath>

#include <gtest/gtest.h>

#include "framework/metrics/metrics.h"
#include "metrics/metrics_test_support.h"

namespace lpvlab {
namespace {

using test::constantImage;
using test::patternImage;
using test::srgb;

constexpr double kC1 = 0.01 * 0.01;  // (K1 L)^2 with L = 1

// Exposure 0: values in [0, 1] are shown as they are.
MetricOptions unexposed() {
  MetricOptions options;
  options.exposureStops = 0.0;
  return options;
}

// For constant images every window has zero variance and covariance, so SSIM is its luminance
// term alone: (2 mu_x mu_y + C1) / (mu_x^2 + mu_y^2 + C1), mu the encoded display luminance.
TEST(Ssim, ConstantImagesHaveTheLuminanceTermAlone) {
  const double r = 0.3, t = 0.5;
  const Image reference = constantImage(20, 20, float(r), float(r), float(r));
  const Image test = constantImage(20, 20, float(t), float(t), float(t));
  const double my = srgb(r), mx = srgb(t);
  const double expected = (2.0 * mx * my + kC1) / (mx * mx + my * my + kC1);
  EXPECT_NEAR(computeMetrics(test, reference, nullptr, unexposed()).ssim, expected, 1e-7);

  // A colour: luminance with the Rec. 709 weights.
  const Image coloured = constantImage(20, 20, 0.2f, 0.4f, 0.6f);
  const double y = srgb(0.2126 * 0.2 + 0.7152 * 0.4 + 0.0722 * 0.6);
  const double colourExpected = (2.0 * y * my + kC1) / (y * y + my * my + kC1);
  EXPECT_NEAR(computeMetrics(coloured, reference, nullptr, unexposed()).ssim, colourExpected, 1e-7);
}

TEST(Ssim, ConstantImagesAtTheDefaultExposure) {
  // The reference's median luminance goes to 0.18 (a scale of 0.18 / 4), so the test's 6 shows
  // as 0.27.
  const Image reference = constantImage(12, 12, 4.0f, 4.0f, 4.0f);
  const Image test = constantImage(12, 12, 6.0f, 6.0f, 6.0f);
  const double my = srgb(0.18), mx = srgb(0.27);
  EXPECT_NEAR(computeMetrics(test, reference).ssim,
              (2.0 * mx * my + kC1) / (mx * mx + my * my + kC1), 1e-6);
}

TEST(Ssim, IsSymmetric) {
  const Image a = patternImage(30, 20, 11);
  const Image b = patternImage(30, 20, 12);
  const double ab = computeMetrics(a, b, nullptr, unexposed()).ssim;
  const double ba = computeMetrics(b, a, nullptr, unexposed()).ssim;
  EXPECT_NEAR(ab, ba, 1e-12);
  EXPECT_LT(ab, 0.99);
}

TEST(Ssim, OppositeStructureIsNegativeButAboveMinusOne) {
  // A vertical sine grating and its negative around the same mean luminance.
  Image reference(32, 32, 3), inverted(32, 32, 3);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) {
        const float wave = 0.3f * std::sin(0.7f * x);
        reference.at(x, y, c) = 0.4f + wave;
        inverted.at(x, y, c) = 0.4f - wave;
      }
  const double ssim = computeMetrics(inverted, reference, nullptr, unexposed()).ssim;
  EXPECT_LT(ssim, 0.0);
  EXPECT_GT(ssim, -1.0);
}

TEST(Ssim, FallsWithNoise) {
  const Image reference = patternImage(32, 32, 13);
  Image slightly = reference, strongly = reference;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    const float noise = (i * 2654435761u % 1000) / 1000.0f - 0.5f;
    slightly.pixels[i] += 0.02f * noise;
    strongly.pixels[i] += 0.2f * noise;
  }
  const double a = computeMetrics(slightly, reference, nullptr, unexposed()).ssim;
  const double b = computeMetrics(strongly, reference, nullptr, unexposed()).ssim;
  EXPECT_LT(a, 1.0);
  EXPECT_LT(b, a);
}

}  // namespace
}  // namespace lpvlab
