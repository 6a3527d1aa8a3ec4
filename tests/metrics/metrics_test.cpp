// The per-value figures (MAE, RMSE, relative MSE, PSNR), masks, the JSON form and the input
// checks of computeMetrics.

#include "framework/metrics/metrics.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "metrics/metrics_test_support.h"

namespace lpvlab {
namespace {

using test::constantImage;
using test::expectError;
using test::patternImage;
using test::plus;

TEST(Metrics, IdenticalImagesHaveNoError) {
  const Image image = patternImage(32, 24, 1);
  const MetricSet m = computeMetrics(image, image);
  EXPECT_EQ(m.mae, 0.0);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.relMse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr) && m.psnr > 0.0) << m.psnr;
  EXPECT_NEAR(m.ssim, 1.0, 1e-12);
  EXPECT_EQ(m.flip, 0.0);
  EXPECT_EQ(m.pixels, 32 * 24);
}

TEST(Metrics, ConstantOffsetHasClosedForms) {
  const float r = 0.5f, d = 0.125f;  // exact in float, so t - r is exactly d
  const Image reference = constantImage(16, 12, r, r, r);
  const Image test = plus(reference, d);
  const MetricSet m = computeMetrics(test, reference);
  EXPECT_NEAR(m.mae, d, 1e-9);
  EXPECT_NEAR(m.rmse, d, 1e-9);
  EXPECT_NEAR(m.relMse, d * d / (r * r + 1e-2), 1e-9);  // the default epsilon
  // Default peak: the reference's maximum, r.
  EXPECT_NEAR(m.psnr, 10.0 * std::log10(r * r / (d * d)), 1e-6);

  MetricOptions options;
  options.psnrPeak = 1.0;
  options.relMseEpsilon = 0.5;
  const MetricSet explicitPeak = computeMetrics(test, reference, nullptr, options);
  EXPECT_NEAR(explicitPeak.psnr, 10.0 * std::log10(1.0 / (d * d)), 1e-6);
  EXPECT_NEAR(explicitPeak.relMse, d * d / (r * r + 0.5), 1e-9);

  // A negative offset of the same size gives the same MAE and RMSE.
  const MetricSet below = computeMetrics(plus(reference, -d), reference);
  EXPECT_NEAR(below.mae, d, 1e-9);
  EXPECT_NEAR(below.rmse, d, 1e-9);
}

TEST(Metrics, ErrorsAverageOverValues) {
  // Two pixels differing by 0.3 and 0.1 in one channel each, the rest equal: 6 values.
  Image reference = constantImage(2, 1, 0.2f, 0.2f, 0.2f);
  Image test = reference;
  test.at(0, 0, 0) += 0.3f;
  test.at(1, 0, 2) -= 0.1f;
  const MetricSet m = computeMetrics(test, reference);
  EXPECT_NEAR(m.mae, (0.3 + 0.1) / 6.0, 1e-7);
  EXPECT_NEAR(m.rmse, std::sqrt((0.09 + 0.01) / 6.0), 1e-7);
  EXPECT_NEAR(m.relMse, (0.09 + 0.01) / 6.0 / (0.04 + 0.01), 1e-6);
}

TEST(Metrics, MaskedOutPixelsChangeNothing) {
  const int w = 40, h = 30;
  const Image reference = patternImage(w, h, 2);
  const Image test = patternImage(w, h, 3);
  const Image mask = test::maskWithHole(w, h, 10, 5, 25, 20);
  const MetricSet masked = computeMetrics(test, reference, &mask);
  EXPECT_EQ(masked.pixels, w * h - 15 * 15);

  // Wild background values in both images (brighter than anything covered, which would move
  // the exposure and the PSNR peak if they were read).
  Image otherTest = test, otherReference = reference;
  for (int y = 5; y < 20; ++y)
    for (int x = 10; x < 25; ++x)
      for (int c = 0; c < 3; ++c) {
        otherTest.at(x, y, c) = 1000.0f * (x + c);
        otherReference.at(x, y, c) = (y % 2) ? 50.0f : -3.0f;
      }
  const MetricSet changed = computeMetrics(otherTest, otherReference, &mask);
  EXPECT_DOUBLE_EQ(changed.mae, masked.mae);
  EXPECT_DOUBLE_EQ(changed.rmse, masked.rmse);
  EXPECT_DOUBLE_EQ(changed.relMse, masked.relMse);
  EXPECT_DOUBLE_EQ(changed.psnr, masked.psnr);
  EXPECT_DOUBLE_EQ(changed.ssim, masked.ssim);
  EXPECT_DOUBLE_EQ(changed.flip, masked.flip);
  EXPECT_DOUBLE_EQ(changed.hdrFlip, masked.hdrFlip);
  EXPECT_EQ(changed.pixels, masked.pixels);

  // Without the mask the same change does show, in every figure.
  const MetricSet unmasked = computeMetrics(otherTest, otherReference);
  EXPECT_NE(unmasked.mae, masked.mae);
  EXPECT_NE(unmasked.rmse, masked.rmse);
  EXPECT_NE(unmasked.relMse, masked.relMse);
  EXPECT_NE(unmasked.psnr, masked.psnr);
  EXPECT_NE(unmasked.ssim, masked.ssim);
  EXPECT_NE(unmasked.flip, masked.flip);
  EXPECT_NE(unmasked.hdrFlip, masked.hdrFlip);
}

TEST(Metrics, MaskedErrorsAreMeansOverCoveredValues) {
  const int w = 20, h = 10;
  const Image reference = patternImage(w, h, 4);
  const Image test = patternImage(w, h, 5);
  Image mask(w, h, 1, 0.0f);
  double absSum = 0.0, squareSum = 0.0;
  int covered = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if ((x * 7 + y * 3) % 5 == 0) continue;
      mask.at(x, y, 0) = 0.25f;  // any non-zero value covers the pixel
      ++covered;
      for (int c = 0; c < 3; ++c) {
        const double d = double(test.at(x, y, c)) - reference.at(x, y, c);
        absSum += std::abs(d);
        squareSum += d * d;
      }
    }
  const MetricSet m = computeMetrics(test, reference, &mask);
  EXPECT_EQ(m.pixels, covered);
  EXPECT_NEAR(m.mae, absSum / (3 * covered), 1e-7);
  EXPECT_NEAR(m.rmse, std::sqrt(squareSum / (3 * covered)), 1e-7);
}

TEST(Metrics, MaskCoveringOnlyEqualPixelsGivesNoError) {
  Image reference = patternImage(8, 8, 6);
  Image test = reference;
  test.at(3, 4, 1) += 0.5f;
  Image mask(8, 8, 1, 1.0f);
  mask.at(3, 4, 0) = 0.0f;
  const MetricSet m = computeMetrics(test, reference, &mask);
  EXPECT_EQ(m.mae, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr));
  EXPECT_NEAR(m.ssim, 1.0, 1e-12);
  EXPECT_EQ(m.flip, 0.0);
  EXPECT_GT(computeMetrics(test, reference).mae, 0.0);
}

TEST(Metrics, JsonWritesInfinitePsnrAsAString) {
  const Image image = patternImage(8, 8, 7);
  const nlohmann::json same = computeMetrics(image, image).toJson();
  EXPECT_EQ(same["psnr"], "inf");
  EXPECT_EQ(same["mae"], 0.0);
  EXPECT_EQ(same["pixels"], 64);
  for (const char* key : {"mae", "rmse", "rel_mse", "psnr", "ssim", "flip", "block_nrmse", "pixels"})
    EXPECT_TRUE(same.contains(key)) << key;

  const MetricSet different = computeMetrics(plus(image, 0.1f), image);
  const nlohmann::json json = different.toJson();
  ASSERT_TRUE(json["psnr"].is_number());
  EXPECT_DOUBLE_EQ(json["psnr"].get<double>(), different.psnr);
  EXPECT_DOUBLE_EQ(json["flip"].get<double>(), different.flip);
  // The text form parses back: no bare inf or nan in it.
  EXPECT_EQ(nlohmann::json::parse(same.dump())["psnr"], "inf");
}

TEST(Metrics, BadInputsAreErrorsNamingTheProblem) {
  const Image a = patternImage(5, 3, 8);
  expectError([&] { computeMetrics(a, patternImage(4, 3, 8)); }, {"5x3", "4x3", "same size"});
  expectError([&] { flipErrorMap(patternImage(4, 3, 8), a); }, {"flipErrorMap", "4x3", "5x3"});

  Image nan = a;
  nan.at(2, 1, 1) = std::numeric_limits<float>::quiet_NaN();
  expectError([&] { computeMetrics(nan, a); }, {"test pixel (2, 1) channel 1", "NaN"});
  expectError([&] { computeMetrics(a, nan); }, {"reference pixel (2, 1) channel 1", "NaN"});
  Image inf = a;
  inf.at(4, 2, 0) = std::numeric_limits<float>::infinity();
  expectError([&] { errorHeatMap(inf, a); }, {"test pixel (4, 2) channel 0", "Inf"});

  expectError([&] { computeMetrics(Image(5, 3, 4), a); }, {"test image has 4 channels", "RGB"});
  expectError([&] { computeMetrics(a, Image(5, 3, 1)); }, {"reference image has 1 channels"});
  expectError([&] { computeMetrics(Image(0, 0, 3), Image(0, 0, 3)); }, {"empty"});

  const Image wrongMask(5, 4, 1, 1.0f);
  expectError([&] { computeMetrics(a, a, &wrongMask); }, {"mask is 5x4", "5x3"});
  const Image rgbMask(5, 3, 3, 1.0f);
  expectError([&] { computeMetrics(a, a, &rgbMask); }, {"mask", "3 channels"});
  const Image emptyMask(5, 3, 1, 0.0f);
  expectError([&] { computeMetrics(a, a, &emptyMask); }, {"covers no pixel"});
  Image nanMask(5, 3, 1, 1.0f);
  nanMask.at(0, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  expectError([&] { computeMetrics(a, a, &nanMask); }, {"mask pixel (0, 0)", "NaN"});

  MetricOptions badPeak;
  badPeak.psnrPeak = 0.0;
  expectError([&] { computeMetrics(a, a, nullptr, badPeak); }, {"PSNR peak", "psnrPeak"});
  const Image black(5, 3, 3, 0.0f);
  expectError([&] { computeMetrics(a, black); }, {"PSNR peak", "reference's maximum"});
  MetricOptions badEpsilon;
  badEpsilon.relMseEpsilon = 0.0;
  expectError([&] { computeMetrics(a, a, nullptr, badEpsilon); }, {"relMseEpsilon"});
  MetricOptions badPpd;
  badPpd.pixelsPerDegree = -1.0;
  expectError([&] { flipErrorMap(a, a, nullptr, badPpd); }, {"pixelsPerDegree"});
}

}  // namespace
}  // namespace lpvlab
