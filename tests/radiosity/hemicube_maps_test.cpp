// The hemicube's delta form factors (seed 004, 3.5): they integrate the cosine-weighted
// hemisphere, so their midpoint sum tends to 1 as the resolution grows, with an error of order
// resolution^-2; normalised, they sum to 1.
#include <cmath>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/radiosity/hemicube_maps.h"

namespace lpvlab {
namespace {

double normalisedSum(const HemicubeMaps& maps) {
  double sum = 0.0;
  for (float v : maps.top) sum += v;
  for (float v : maps.side) sum += 4.0 * v;
  return sum;
}

TEST(HemicubeMaps, MidpointSumTendsToOneAtSecondOrder) {
  double previous = 0.0;
  for (int resolution : {8, 16, 32, 64, 128, 256}) {
    const HemicubeMaps maps = hemicubeMaps(resolution);
    const double error = std::abs(maps.rawSum - 1.0);
    // Stated bound: the midpoint rule on these smooth integrands, |error| <= 1 / resolution^2.
    EXPECT_LE(error, 1.0 / (double(resolution) * resolution)) << resolution;
    if (previous > 0.0) {
      // Halving the pixel divides the error by about 4 (between 3 and 5).
      EXPECT_GT(previous / error, 3.0) << resolution;
      EXPECT_LT(previous / error, 5.0) << resolution;
    }
    previous = error;
    EXPECT_NEAR(normalisedSum(maps), 1.0, 1e-5) << resolution;
  }
}

TEST(HemicubeMaps, TopFaceHoldsTheShareOfTheCosineLobeWithinFortyFiveDegreesOfSquare) {
  // The top face sees the pyramid |x|, |y| <= z. Its share of the cosine-weighted hemisphere is
  // the integral of the delta form factor over [-1, 1]^2; the side faces get the rest. Check the
  // centre pixel against the closed form dA / pi (cos^4 at the pole).
  const HemicubeMaps maps = hemicubeMaps(256);
  const double pixel = 2.0 / 256, u = 0.5 * pixel;
  const double expected = pixel * pixel / (M_PI * std::pow(2 * u * u + 1.0, 2.0)) / maps.rawSum;
  EXPECT_NEAR(maps.top[128 * 256 + 128], expected, 1e-6 * expected);
  // Side pixels vanish at the base (cosine 0) and the corners of the top face are the weakest
  // there.
  EXPECT_LT(maps.side[0], maps.side[127 * 256]);
  EXPECT_LT(maps.top[0], maps.top[128 * 256 + 128]);
}

TEST(HemicubeMaps, OddOrOutOfRangeResolutionsAreErrors) {
  for (int bad : {0, 1, 3, 63, -2, 8194}) EXPECT_THROW(hemicubeMaps(bad), Error) << bad;
}

}  // namespace
}  // namespace lpvlab
