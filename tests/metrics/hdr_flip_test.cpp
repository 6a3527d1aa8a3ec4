// HDR-FLIP: agreement with NVIDIA's reference code, its exposure range in closed form, the
// invariants (zero for identical images, radiance units, at least LDR-FLIP at every exposure it
// spans), the errors it exists to see (a highlight above display white), and bad exposures.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/metrics/flip.h"
#include "framework/metrics/hdr_flip.h"
#include "framework/metrics/metrics.h"
#include "metrics/metrics_test_support.h"

namespace lpvlab {
namespace {

using test::constantImage;
using test::patternImage;

PixelMask everyPixel(const Image& image) {
  return checkInputs("test", image, image, nullptr);
}

constexpr double kPpd = 0.7 * 3840.0 / 0.7 * 3.14159265358979323846 / 180.0;  // FLIP's default

// About 10 stops of smooth variation with a highlight of 400 (far above white at the median's
// exposure); the test is 0.7x on the left, 1.25x on the right plus an offset, and its highlight
// is 300 and two pixels to the right.
void hdrPair(Image& reference, Image& test) {
  const int w = 48, h = 32;
  reference = Image(w, h, 3);
  test = Image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const float e =
            5.0f + 5.0f * std::sin(0.13f * x + 0.07f * y) * std::cos(0.05f * x - 0.11f * y);
        float v = 0.01f * std::exp2(e) * (0.8f + 0.2f * std::sin(0.9f * x + 1.7f * c));
        const float dx = x - 30.0f, dy = y - 12.0f;
        if (dx * dx + dy * dy < 9.0f) v += 400.0f;
        reference.at(x, y, c) = v;
        float t = v * (x < 24 ? 0.7f : 1.25f) + 0.05f * (1.0f + std::sin(0.5f * y + c));
        const float ex = x - 32.0f;
        if (ex * ex + dy * dy < 9.0f) t += 300.0f;
        test.at(x, y, c) = t;
      }
}

// The values of NVIDIA's FLIP.h (github.com/NVlabs/flip at 1eb247c, version 1.6: FLIP::evaluate
// with useHDR, the ACES tone mapper and the exposures it computes; float32) on the same images,
// built with the same float expressions. Our computation is in double, hence 1e-5. On the same
// driver its LDR-FLIP gave Flip.MatchesTheReferenceImplementation's values to 1e-6.
TEST(HdrFlip, MatchesTheReferenceImplementation) {
  Image reference, test;
  hdrPair(reference, test);
  const HdrFlipExposures e = hdrFlipExposures(reference, everyPixel(reference));
  EXPECT_NEAR(e.start, -7.560608, 1e-5);
  EXPECT_NEAR(e.stop, 2.846551, 1e-5);
  EXPECT_EQ(e.count, 11);
  const HdrFlipMap map = hdrFlipErrorMap(test, reference);
  EXPECT_NEAR(map.error.at(10, 10, 0), 0.3934037, 1e-5);
  EXPECT_NEAR(map.error.at(40, 20, 0), 0.2852089, 1e-5);
  EXPECT_NEAR(map.error.at(0, 0, 0), 0.1988827, 1e-5);
  EXPECT_NEAR(map.error.at(30, 12, 0), 0.2911591, 1e-5);  // in the highlight
  EXPECT_NEAR(map.error.at(5, 25, 0), 0.7343619, 1e-5);
  EXPECT_NEAR(computeMetrics(test, reference).hdrFlip, 0.4345486, 1e-5);
}

// start = log2(x85 / Ymax), stop = log2(x85 / Ymedian) with t(x85) = 0.85.
TEST(HdrFlip, ExposureRangeInClosedForm) {
  // Grey pixels 0.5, 1, 2, 4, 64: luminance is the grey value, the median is 2.
  Image reference(5, 1, 3);
  const float greys[] = {0.5f, 1.0f, 2.0f, 4.0f, 64.0f};
  for (int x = 0; x < 5; ++x)
    for (int c = 0; c < 3; ++c) reference.at(x, 0, c) = greys[x];
  const HdrFlipExposures e = hdrFlipExposures(reference, everyPixel(reference));
  // Solve t(x) = 0.85 by bisection on the curve's rise, independently of the quadratic formula.
  double low = 0.0, high = 100.0;
  for (int i = 0; i < 200; ++i) {
    const double middle = 0.5 * (low + high);
    (acesToneMap(middle) < 0.85 ? low : high) = middle;
  }
  const double x85 = 0.5 * (low + high);
  EXPECT_NEAR(e.start, std::log2(x85 / 64.0), 1e-9);
  EXPECT_NEAR(e.stop, std::log2(x85 / 2.0), 1e-9);
  EXPECT_EQ(e.count, 5);  // ceil(log2(64 / 2)) = 5 stops
  // The tone curve: 0 at 0, rising, towards 0.6^2 2.51 / (0.6^2 2.43) > 1 (so it is clamped).
  EXPECT_EQ(acesToneMap(0.0), 0.0);
  EXPECT_LT(acesToneMap(0.1), acesToneMap(0.2));
  EXPECT_NEAR(acesToneMap(1e9), 2.51 / 2.43, 1e-6);
}

TEST(HdrFlip, MostlyBlackAndBlackReferences) {
  // Three of five pixels black: the median of the lit ones (4 and 16: the element at n/2 = 1 of
  // the sorted pair, 16) sets the stop instead of an infinite one.
  Image reference(5, 1, 3, 0.0f);
  for (int c = 0; c < 3; ++c) reference.at(1, 0, c) = 4.0f, reference.at(3, 0, c) = 16.0f;
  const HdrFlipExposures e = hdrFlipExposures(reference, everyPixel(reference));
  EXPECT_TRUE(std::isfinite(e.stop));
  EXPECT_NEAR(e.stop, e.start, 1e-12);  // median = max = 16
  EXPECT_EQ(e.count, 2);
  // A black reference: one exposure at 0, and a black test agrees with it exactly.
  const Image black = constantImage(8, 8, 0.0f, 0.0f, 0.0f);
  const HdrFlipExposures none = hdrFlipExposures(black, everyPixel(black));
  EXPECT_EQ(none.start, 0.0);
  EXPECT_EQ(none.stop, 0.0);
  const Image white = constantImage(8, 8, 1.0f, 1.0f, 1.0f);
  const Image same = hdrFlipErrorMap(black, black).error;
  EXPECT_EQ(*std::max_element(same.pixels.begin(), same.pixels.end()), 0.0f);
  EXPECT_GT(hdrFlipErrorMap(white, black).error.at(4, 4, 0), 0.5f);
}

TEST(HdrFlip, IdenticalImagesAreZeroAndTheUnitsDoNotMatter) {
  Image reference, test;
  hdrPair(reference, test);
  EXPECT_EQ(computeMetrics(reference, reference).hdrFlip, 0.0);
  // Both images 1024x brighter: the range moves down 10 stops, and every tone-mapped image is
  // the same up to float rounding.
  Image brightReference = reference, brightTest = test;
  for (float& v : brightReference.pixels) v *= 1024.0f;
  for (float& v : brightTest.pixels) v *= 1024.0f;
  const HdrFlipExposures e = hdrFlipExposures(reference, everyPixel(reference));
  const HdrFlipExposures bright = hdrFlipExposures(brightReference, everyPixel(brightReference));
  EXPECT_NEAR(bright.start, e.start - 10.0, 1e-9);
  EXPECT_NEAR(bright.stop, e.stop - 10.0, 1e-9);
  EXPECT_NEAR(computeMetrics(brightTest, brightReference).hdrFlip,
              computeMetrics(test, reference).hdrFlip, 1e-6);
}

// The per-pixel maximum over the exposures: with one exposure it is LDR-FLIP of the tone-mapped
// images, and over a range that includes it, at least that everywhere.
TEST(HdrFlip, IsTheLargestLdrFlipOverItsExposures) {
  const Image reference = patternImage(32, 24, 31), test = patternImage(32, 24, 32);
  const PixelMask mask = everyPixel(reference);
  auto toneMapped = [](Image image, double stops) {
    for (float& v : image.pixels) v = float(std::min(1.0, acesToneMap(v * std::exp2(stops))));
    return image;
  };
  const Plane single = hdrFlip(test, reference, mask, kPpd, {1.5, 1.5, 2}).error;
  const Plane ldr = ldrFlip(toneMapped(test, 1.5), toneMapped(reference, 1.5), mask, kPpd);
  const HdrFlipMaps range = hdrFlip(test, reference, mask, kPpd, {-2.5, 1.5, 9});  // 1.5 the last
  bool someLarger = false;
  for (std::size_t p = 0; p < ldr.values.size(); ++p) {
    EXPECT_NEAR(single[p], ldr[p], 1e-6);
    EXPECT_GE(range.error[p], ldr[p] - 1e-6);
    EXPECT_GE(range.exposure[p], 0.0);
    EXPECT_LE(range.exposure[p], 1.0);
    someLarger = someLarger || range.error[p] > ldr[p] + 1e-3;
  }
  EXPECT_TRUE(someLarger);
}

// What LDR-FLIP at the median's exposure cannot see: a highlight 2x too bright, above display
// white in both images. HDR-FLIP's brightest exposures show it.
TEST(HdrFlip, SeesAnErrorInAHighlightThatLdrFlipClampsAway) {
  Image reference = constantImage(48, 48, 0.2f, 0.2f, 0.2f);
  for (int y = 16; y < 32; ++y)
    for (int x = 16; x < 32; ++x)
      for (int c = 0; c < 3; ++c) reference.at(x, y, c) = 50.0f;
  Image test = reference;
  for (int y = 16; y < 32; ++y)
    for (int x = 16; x < 32; ++x)
      for (int c = 0; c < 3; ++c) test.at(x, y, c) = 100.0f;
  const Image ldr = flipErrorMap(test, reference);
  const HdrFlipMap hdr = hdrFlipErrorMap(test, reference);
  EXPECT_EQ(ldr.at(24, 24, 0), 0.0f);  // both white on screen
  EXPECT_GT(hdr.error.at(24, 24, 0), 0.1);
  EXPECT_EQ(hdr.error.at(2, 2, 0), 0.0f);  // out of every filter's reach, identical
}

TEST(HdrFlip, NegativeValuesShowAsBlack) {
  // SH ringing: a test pixel below zero looks as a black one does (the reference code's rational
  // curve would show -1 as white).
  const Image reference = patternImage(16, 16, 33);
  Image negative = reference, black = reference;
  for (int c = 0; c < 3; ++c) negative.at(8, 8, c) = -1.0f, black.at(8, 8, c) = 0.0f;
  EXPECT_DOUBLE_EQ(computeMetrics(negative, reference).hdrFlip,
                   computeMetrics(black, reference).hdrFlip);
}

TEST(HdrFlip, BadExposuresAreErrors) {
  const Image image = patternImage(8, 8, 34);
  const PixelMask mask = everyPixel(image);
  EXPECT_THROW(hdrFlip(image, image, mask, kPpd, {1.0, 0.0, 4}), Error);
  EXPECT_THROW(hdrFlip(image, image, mask, kPpd, {0.0, 1.0, 1}), Error);
  EXPECT_THROW(hdrFlip(image, image, mask, kPpd, {NAN, 1.0, 4}), Error);
}

}  // namespace
}  // namespace lpvlab
