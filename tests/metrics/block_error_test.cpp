// Block nRMSE (block_error.h) against what it must be by construction: a constant offset c gives
// c over the reference's mean; noise of zero mean within each block gives 0 while the pixel RMSE
// does not; blocks are averaged over their covered pixels only; a black reference gives 0 for a
// black test and +inf otherwise.

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "framework/metrics/block_error.h"
#include "framework/metrics/metrics.h"
#include "metrics/metrics_test_support.h"

namespace lpvlab {
namespace {

PixelMask everything(int w, int h) {
  return PixelMask{w, h, std::vector<std::uint8_t>(std::size_t(w) * h, 1), std::int64_t(w) * h};
}

TEST(BlockError, AConstantOffsetIsItsRatioToTheReferencesMean) {
  const Image reference = test::patternImage(37, 21, 3);  // blocks cut at the right and bottom
  // The mean of block means is not the pixel mean when edge blocks are smaller: compute it so.
  double blockMeans = 0.0;
  int blocks = 0;
  for (int by = 0; by < 21; by += 8)
    for (int bx = 0; bx < 37; bx += 8) {
      for (int c = 0; c < 3; ++c) {
        double s = 0.0;
        int n = 0;
        for (int y = by; y < std::min(by + 8, 21); ++y)
          for (int x = bx; x < std::min(bx + 8, 37); ++x) s += reference.at(x, y, c), ++n;
        blockMeans += s / n;
      }
      ++blocks;
    }
  const double mean = blockMeans / (3.0 * blocks);
  EXPECT_NEAR(blockNrmse(test::plus(reference, 0.05f), reference, everything(37, 21)), 0.05 / mean, 1e-6);
  EXPECT_EQ(blockNrmse(reference, reference, everything(37, 21)), 0.0);
}

TEST(BlockError, NoiseOfZeroMeanInEveryBlockIsInvisibleToItButNotToTheRmse) {
  const Image reference = test::constantImage(32, 32, 0.3f, 0.2f, 0.1f);
  Image noisy = reference;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) noisy.at(x, y, c) += ((x + y) % 2 ? 0.05f : -0.05f);  // a checkerboard
  EXPECT_NEAR(blockNrmse(noisy, reference, everything(32, 32)), 0.0, 1e-7);
  const MetricSet m = computeMetrics(noisy, reference);
  EXPECT_NEAR(m.rmse, 0.05, 1e-6);
  EXPECT_NEAR(m.blockNrmse, 0.0, 1e-7);
}

TEST(BlockError, BlocksAverageTheirCoveredPixelsOnly) {
  // One 8x8 block; the test is wrong only where the mask leaves the pixels out, and right where
  // it covers them: no error. Covering one wrong pixel of the 64 gives its error over 1, not 64.
  const Image reference = test::constantImage(8, 8, 1.0f, 1.0f, 1.0f);
  Image test = reference;
  test.at(0, 0, 0) = test.at(0, 0, 1) = test.at(0, 0, 2) = 3.0f;
  PixelMask mask = everything(8, 8);
  mask.covered[0] = 0;
  mask.count = 63;
  EXPECT_EQ(blockNrmse(test, reference, mask), 0.0);
  PixelMask one{8, 8, std::vector<std::uint8_t>(64, 0), 1};
  one.covered[0] = 1;
  EXPECT_NEAR(blockNrmse(test, reference, one), 2.0, 1e-12);
}

TEST(BlockError, ABlackReferenceGivesZeroOrInfinity) {
  const Image black = test::constantImage(16, 16, 0.0f, 0.0f, 0.0f);
  EXPECT_EQ(blockNrmse(black, black, everything(16, 16)), 0.0);
  EXPECT_EQ(blockNrmse(test::plus(black, 0.1f), black, everything(16, 16)),
            std::numeric_limits<double>::infinity());
  // Written as "inf" in JSON, as an infinite PSNR is (computeMetrics refuses a black reference
  // for its PSNR peak, so the set is made here).
  MetricSet metrics;
  metrics.blockNrmse = blockNrmse(test::plus(black, 0.1f), black, everything(16, 16));
  EXPECT_EQ(metrics.toJson()["block_nrmse"], "inf");
  EXPECT_EQ(nlohmann::json::parse(metrics.toJson().dump())["block_nrmse"], "inf");
}

}  // namespace
}  // namespace lpvlab
