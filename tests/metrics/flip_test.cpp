// FLIP: zero for identical images, its value for black against white, range, monotonicity, the
// feature term (in closed form, and against a moved line), agreement with the reference code, the
// HDR exposure handling, the viewing distance, and the false-colour heat map.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "framework/metrics/metrics.h"
#include "metrics/metrics_test_support.h"

namespace lpvlab {
namespace {

using test::constantImage;
using test::patternImage;
using test::plus;

MetricOptions unexposed() {
  MetricOptions options;
  options.exposureStops = 0.0;
  return options;
}

double mapMax(const Image& map) { return *std::max_element(map.pixels.begin(), map.pixels.end()); }

TEST(Flip, IdenticalImagesAreZeroEverywhere) {
  const Image image = patternImage(40, 30, 21);
  const Image map = flipErrorMap(image, image);
  ASSERT_EQ(map.channels, 1);
  ASSERT_EQ(map.width, 40);
  ASSERT_EQ(map.height, 30);
  EXPECT_EQ(mapMax(map), 0.0);
  EXPECT_EQ(computeMetrics(image, image).flip, 0.0);
}

// Constant images have no features, so FLIP is the colour term: HyAB(white, black) = 100
// (L* 100 against 0, no chroma), against cmax = HyAB of Hunt-adjusted green and blue, from the
// published CIELAB of sRGB green (87.735, -86.183, 83.179) and blue (32.297, 79.188, -107.860).
TEST(Flip, BlackAgainstWhiteIsNearlyOne) {
  const double gL = 87.735, ga = -86.183 * 0.01 * gL, gb = 83.179 * 0.01 * gL;
  const double bL = 32.297, ba = 79.188 * 0.01 * bL, bb = -107.860 * 0.01 * bL;
  const double cmax = std::pow(std::abs(gL - bL) + std::hypot(ga - ba, gb - bb), 0.7);
  const double d = std::pow(100.0, 0.7);
  ASSERT_GT(d, 0.4 * cmax);  // above the knee
  const double expected = 0.95 + (d - 0.4 * cmax) / (0.6 * cmax) * 0.05;

  const Image black = constantImage(24, 24, 0.0f, 0.0f, 0.0f);
  const Image white = constantImage(24, 24, 1.0f, 1.0f, 1.0f);
  const Image map = flipErrorMap(white, black, nullptr, unexposed());
  for (float value : map.pixels) EXPECT_NEAR(value, expected, 1e-3);
  const double flip = computeMetrics(black, white, nullptr, unexposed()).flip;
  EXPECT_NEAR(flip, expected, 1e-3);
  EXPECT_GT(flip, 0.95);
}

TEST(Flip, SmallColourShiftIsSmallAndPositive) {
  const Image reference = constantImage(24, 24, 0.5f, 0.5f, 0.5f);
  const Image test = constantImage(24, 24, 0.52f, 0.5f, 0.5f);
  const double flip = computeMetrics(test, reference, nullptr, unexposed()).flip;
  EXPECT_GT(flip, 0.0);
  EXPECT_LT(flip, 0.1);
}

TEST(Flip, StaysInTheUnitInterval) {
  // Unrelated noisy images, saturated colours included.
  Image a(48, 48, 3), b(48, 48, 3);
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    a.pixels[i] = float((i * 2654435761u) % 1000) / 999.0f;
    b.pixels[i] = (i * 40503u) % 3 == 0 ? 1.0f : 0.0f;
  }
  const Image map = flipErrorMap(a, b, nullptr, unexposed());
  for (float value : map.pixels) {
    EXPECT_GE(value, 0.0f);
    EXPECT_LE(value, 1.0f);
  }
  EXPECT_GT(mapMax(map), 0.5);
}

TEST(Flip, GrowsWithTheOffset) {
  const Image reference = patternImage(32, 32, 22);  // values in [0.1, 0.6]: no clamping below
  double previous = 0.0;
  for (float offset : {0.005f, 0.01f, 0.02f, 0.05f, 0.1f, 0.2f, 0.35f}) {
    const double flip =
        computeMetrics(plus(reference, offset), reference, nullptr, unexposed()).flip;
    EXPECT_GT(flip, previous) << "offset " << offset;
    previous = flip;
  }
}

// A thin line moved by two pixels against a uniform shift with the same squared error: MSE
// cannot tell them apart, but FLIP sees the moved feature as a far larger (local) error. The mean
// FLIP is not compared: FLIP is concave in the difference, so spreading the same energy over
// every pixel raises the mean; the point is how bad the moved line looks where it is.
TEST(Flip, MovedThinLineIsWorseThanAUniformShiftOfEqualEnergy) {
  const int w = 64, h = 32;
  const float grey = 0.18f, line = 0.8f;
  Image reference = constantImage(w, h, grey, grey, grey);
  Image moved = reference;
  for (int y = 0; y < h; ++y)
    for (int c = 0; c < 3; ++c) reference.at(30, y, c) += line, moved.at(32, y, c) += line;
  // Equal energy: w h delta^2 = 2 h line^2.
  const Image shifted = plus(reference, line * std::sqrt(2.0f / w));

  const MetricSet movedMetrics = computeMetrics(moved, reference, nullptr, unexposed());
  const MetricSet shiftedMetrics = computeMetrics(shifted, reference, nullptr, unexposed());
  EXPECT_NEAR(movedMetrics.rmse, shiftedMetrics.rmse, 1e-6);

  const Image movedMap = flipErrorMap(moved, reference, nullptr, unexposed());
  const Image shiftedMap = flipErrorMap(shifted, reference, nullptr, unexposed());
  EXPECT_GT(mapMax(movedMap), mapMax(shiftedMap));
  // The error is where the line was and where it is (not halfway: x = 31 sees the two lines
  // mirrored, hence the same filtered values and no error), and beyond the filters' reach (radius
  // 10 at 67 pixels per degree) the images agree exactly.
  for (int y = 0; y < h; ++y) {
    EXPECT_EQ(movedMap.at(5, y, 0), 0.0f);
    EXPECT_EQ(movedMap.at(60, y, 0), 0.0f);
    EXPECT_GT(movedMap.at(30, y, 0), mapMax(shiftedMap));
    EXPECT_GT(movedMap.at(32, y, 0), mapMax(shiftedMap));
  }
}

// The feature term in closed form. The test adds to a constant grey an achromatic step of +-a that
// is antisymmetric about column x0 (0 on it). Every contrast sensitivity filter is symmetric, so
// at x0 the filtered test is the plain grey and the colour term is that of two constant images,
// whose FLIP has no feature term. The edge filter (positive weights summing to 1 on one side,
// negative to -1 on the other) answers 2a there, the reference 0; the point filter, symmetric,
// answers 0 to both. So at x0: FLIP = colour^(1 - dEf), dEf = (2a / sqrt(2))^0.5.
TEST(Flip, FeatureTermOfAnEdgeInClosedForm) {
  const int w = 64, h = 24, x0 = 32;
  const float grey = 0.35f, a = 0.1f;
  const Image reference = constantImage(w, h, 0.3f, 0.3f, 0.3f);
  const Image flat = constantImage(w, h, grey, grey, grey);
  Image edge = flat;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) edge.at(x, y, c) += x > x0 ? a : x < x0 ? -a : 0.0f;

  const double colour = flipErrorMap(flat, reference, nullptr, unexposed()).at(x0, 12, 0);
  ASSERT_GT(colour, 0.0);
  const double feature = std::sqrt(2.0 * a / std::sqrt(2.0));
  const Image map = flipErrorMap(edge, reference, nullptr, unexposed());
  for (int y = 0; y < h; ++y) EXPECT_NEAR(map.at(x0, y, 0), std::pow(colour, 1.0 - feature), 1e-5);
}

// Colourful smooth images, against values from a transcription of NVIDIA's Python reference
// (flip_api.py, compute_ldrflip, float32, OpenCV's filter2D with replicated borders) on the same
// linear values at 67.02 pixels per degree. Catches any constant or step that differs.
TEST(Flip, MatchesTheReferenceImplementation) {
  const int w = 48, h = 32;
  Image reference(w, h, 3), test(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        reference.at(x, y, c) = 0.5f + 0.4f * std::sin(0.37f * x + 0.23f * y + 2.0f * c);
        test.at(x, y, c) = reference.at(x, y, c) +
                           0.1f * std::sin(0.11f * x - 0.3f * y + c) * (x > 20 ? 1.0f : 0.3f);
      }
  const Image map = flipErrorMap(test, reference, nullptr, unexposed());
  EXPECT_NEAR(map.at(10, 10, 0), 0.1197557, 1e-5);
  EXPECT_NEAR(map.at(40, 20, 0), 0.3033639, 1e-5);
  EXPECT_NEAR(map.at(0, 0, 0), 0.1356083, 1e-5);
  EXPECT_NEAR(computeMetrics(test, reference, nullptr, unexposed()).flip, 0.2231331, 1e-5);
}

// HDR handling: with the default exposure (the reference's median luminance to 0.18) the
// display-referred metrics do not depend on the radiance units.
TEST(Flip, DefaultExposureIgnoresTheUnits) {
  const Image reference = patternImage(32, 32, 23);
  const Image test = patternImage(32, 32, 24);
  Image bigReference = reference, bigTest = test;
  for (float& v : bigReference.pixels) v *= 1000.0f;
  for (float& v : bigTest.pixels) v *= 1000.0f;
  const MetricSet small = computeMetrics(test, reference);
  const MetricSet big = computeMetrics(bigTest, bigReference);
  EXPECT_NEAR(big.flip, small.flip, 1e-5);
  EXPECT_NEAR(big.ssim, small.ssim, 1e-5);
  EXPECT_GT(small.flip, 0.0);
  EXPECT_NEAR(big.mae, 1000.0 * small.mae, 1e-3 * big.mae);  // the per-value figures do scale
}

TEST(Flip, ExposureClampsToTheDisplayRange) {
  // At +20 stops both images are white on screen: nothing to see.
  const Image reference = patternImage(16, 16, 25);
  const Image test = patternImage(16, 16, 26);
  MetricOptions bright;
  bright.exposureStops = 20.0;
  const MetricSet m = computeMetrics(test, reference, nullptr, bright);
  EXPECT_EQ(m.flip, 0.0);
  EXPECT_NEAR(m.ssim, 1.0, 1e-12);
  EXPECT_GT(m.mae, 0.0);
}

TEST(Flip, FewerPixelsPerDegreeBlurLess) {
  // Seen from closer (fewer pixels per degree) a one-pixel checker is less blurred by the
  // contrast sensitivity filters, so its difference from flat grey shows more.
  Image checker(32, 32, 3);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) checker.at(x, y, c) = (x + y) % 2 ? 0.6f : 0.2f;
  const Image grey = constantImage(32, 32, 0.4f, 0.4f, 0.4f);
  MetricOptions far = unexposed(), near = unexposed();
  near.pixelsPerDegree = 10.0;
  EXPECT_GT(computeMetrics(checker, grey, nullptr, near).flip,
            computeMetrics(checker, grey, nullptr, far).flip);
}

TEST(HeatMap, MagmaForErrorsGreyForBackground) {
  const Image reference = constantImage(40, 8, 0.0f, 0.0f, 0.0f);
  Image test = reference;
  for (int y = 0; y < 8; ++y)
    for (int x = 28; x < 40; ++x)
      for (int c = 0; c < 3; ++c) test.at(x, y, c) = 1.0f;  // the right 12 columns white
  Image mask(40, 8, 1, 1.0f);
  mask.at(0, 0, 0) = 0.0f;
  const Image heat = errorHeatMap(test, reference, &mask, unexposed());
  ASSERT_EQ(heat.channels, 3);
  ASSERT_EQ(heat.width, 40);
  for (float value : heat.pixels) {
    EXPECT_GE(value, 0.0f);
    EXPECT_LE(value, 1.0f);
  }
  // Linear values whose sRGB encoding is the colour map's: black-ish for no error, pale yellow
  // (magma near 1) for a large one, sRGB 0.5 grey for background.
  EXPECT_NEAR(test::srgb(heat.at(1, 4, 2)), 0.0139, 2e-3);  // out of the filters' reach: FLIP 0
  EXPECT_NEAR(test::srgb(heat.at(39, 4, 0)), 0.99, 0.01);   // black against white: FLIP 0.97
  EXPECT_GT(test::srgb(heat.at(39, 4, 1)), 0.85);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(test::srgb(heat.at(0, 0, c)), 0.5, 1e-4);
}

TEST(HeatMap, FalseColourMapsItsRangeOntoTheRampAndTheBarRunsBottomToTop) {
  Image values(4, 1, 1);
  values.pixels = {-1.0f, 2.0f, 6.0f, 9.0f};  // below, at, above the range [2, 6]; and masked
  Image mask(4, 1, 1, 1.0f);
  mask.pixels[3] = 0.0f;
  const Image heat = falseColour(values, 2.0f, 6.0f, &mask);
  EXPECT_NEAR(test::srgb(heat.at(0, 0, 2)), 0.0139, 2e-3);  // clamped to the low end: black
  EXPECT_NEAR(test::srgb(heat.at(1, 0, 2)), 0.0139, 2e-3);
  EXPECT_NEAR(test::srgb(heat.at(2, 0, 0)), 0.9871, 2e-3);  // the high end: pale yellow
  EXPECT_NEAR(test::srgb(heat.at(2, 0, 2)), 0.7495, 2e-3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(test::srgb(heat.at(3, 0, c)), 0.5, 1e-4);
  // The bar: after the image and a gap, the top row the ramp's top, the bottom row its bottom.
  const Image tall = falseColour(Image(10, 30, 1, 4.0f), 2.0f, 6.0f);
  const Image keyed = withColourBar(tall);
  ASSERT_GT(keyed.width, tall.width + 2);
  EXPECT_NEAR(test::srgb(keyed.at(keyed.width - 1, 0, 0)), 0.9871, 2e-3);
  EXPECT_NEAR(test::srgb(keyed.at(keyed.width - 1, 29, 2)), 0.0139, 2e-3);
  EXPECT_NEAR(keyed.at(4, 7, 1), tall.at(4, 7, 1), 0.0f);  // the image itself unchanged
  // Bad input: more than one channel, an empty range.
  EXPECT_THROW(falseColour(Image(2, 2, 3), 0.0f, 1.0f), Error);
  EXPECT_THROW(falseColour(values, 1.0f, 1.0f), Error);
}

}  // namespace
}  // namespace lpvlab
