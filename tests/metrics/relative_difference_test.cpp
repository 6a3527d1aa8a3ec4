// relativeDifference (framework/metrics/relative_difference.h) against closed forms: identical
// images differ by 0; a uniform 1% change by 0.01 / (1 + 1e-3); the 99th percentile is the
// nearest-rank one of a known spread; black images, the mask, and bad inputs.

#include <gtest/gtest.h>

#include <cmath>

#include "error_support.h"
#include "framework/metrics/relative_difference.h"

namespace lpvlab {
namespace {

Image filled(int w, int h, float v) { return Image(w, h, 3, v); }

TEST(RelativeDifference, ClosedForms) {
  const Image r = filled(10, 10, 2.0f);
  const RelativeDifference same = relativeDifference(r, r);
  EXPECT_EQ(same.mean, 0.0);
  EXPECT_EQ(same.p99, 0.0);
  EXPECT_EQ(same.max, 0.0);
  EXPECT_EQ(same.values, 300);
  EXPECT_DOUBLE_EQ(same.epsilon, 2e-3);

  // Every value 1% off: |t - r| / (|r| + 1e-3 |r|) = 0.01 / 1.001, whatever the units.
  const Image t = filled(10, 10, 2.02f);
  const RelativeDifference one = relativeDifference(t, r);
  EXPECT_NEAR(one.mean, double(2.02f - 2.0f) / (2.0 * 1.001), 1e-12);
  EXPECT_NEAR(one.p99, one.mean, 1e-12);
  EXPECT_NEAR(one.max, one.mean, 1e-12);
}

TEST(RelativeDifference, NinetyNinthPercentileIsTheNearestRank) {
  // 100 pixels x 3 values: pixel i off by i / 1000 of the reference 1 (relative (i / 1000) /
  // (1 + 1e-3)). Nearest rank 0.99 * 300 = 297: the 297th smallest value, pixel 98's.
  Image r = filled(100, 1, 1.0f), t = filled(100, 1, 1.0f);
  for (int i = 0; i < 100; ++i)
    for (int c = 0; c < 3; ++c) t.at(i, 0, c) = 1.0f + float(i) / 1000.0f;
  const RelativeDifference d = relativeDifference(t, r);
  const auto relative = [](int i) { return double(1.0f + float(i) / 1000.0f - 1.0f) / 1.001; };
  EXPECT_NEAR(d.p99, relative(98), 1e-12);
  EXPECT_NEAR(d.max, relative(99), 1e-12);
  double sum = 0.0;
  for (int i = 0; i < 100; ++i) sum += 3.0 * relative(i);
  EXPECT_NEAR(d.mean, sum / 300.0, 1e-12);
}

TEST(RelativeDifference, BlackImagesAndTheMask) {
  const Image black = filled(4, 4, 0.0f);
  EXPECT_EQ(relativeDifference(black, black).mean, 0.0);
  Image lit = black;
  lit.at(0, 0, 0) = 1.0f;  // one value of 48 lit where the reference is black: wholly different
  const RelativeDifference d = relativeDifference(lit, black);
  EXPECT_DOUBLE_EQ(d.mean, 1.0 / 48.0);
  EXPECT_EQ(d.max, 1.0);

  // Background pixels (mask 0) count for nothing: the lit pixel masked out, the images agree.
  Image mask(4, 4, 1, 1.0f);
  mask.at(0, 0, 0) = 0.0f;
  const RelativeDifference masked = relativeDifference(lit, black, &mask);
  EXPECT_EQ(masked.mean, 0.0);
  EXPECT_EQ(masked.values, 45);
}

TEST(RelativeDifference, BadInputsAreErrors) {
  const Image r = filled(4, 4, 1.0f);
  EXPECT_TRUE(test::contains(test::errorOf([&] { relativeDifference(filled(5, 4, 1.0f), r); }), "4x4"));
  Image nan = r;
  nan.at(1, 1, 1) = std::nanf("");
  EXPECT_TRUE(test::contains(test::errorOf([&] { relativeDifference(nan, r); }), "not finite"));
}

}  // namespace
}  // namespace lpvlab
