#pragma once
// Statistical comparison of Monte Carlo images: per-value z-scores against the variance images
// the path tracer reports, tested at a Sidak-corrected level so that the whole image (every
// channel of every pixel) is rejected by chance with probability familyAlpha.
//
// Each channel of each pixel is one test: z = (a - b) / sqrt(varA + varB) (b exact: varB = 0).
// The standard error is at least relativeFloor * max(|a|, |b|): means of float samples are only
// that precise, and a noise-free estimate (variance 0) must still be allowed its rounding.
// Values with a non-finite variance (fewer than 2 samples) are not tested.

#include <cstdint>

#include "framework/io/image.h"

namespace lpvlab {

struct ComparisonResult {
  std::int64_t pixels = 0;    // pixels with at least one tested channel
  std::int64_t tests = 0;     // tested values (pixel channels)
  std::int64_t rejected = 0;  // tests with |z| above the threshold
  // The |z| critical value, two-sided at the Sidak per-test level 1 - (1 - alpha)^(1 / tests).
  double threshold = 0.0;
  // tests * the per-test level: the rejections expected when nothing differs (about alpha).
  double expectedRejected = 0.0;
  double maxAbsZ = 0.0;
  double meanZ = 0.0;  // over tests; near 0 when the estimates are unbiased
  // Per pixel, the largest |z| of its channels (0 where untested): where the images differ, for
  // an error map or for checking that rejections lie on edges.
  Image pixelMaxAbsZ;
  bool rejectedAt(int x, int y) const { return pixelMaxAbsZ.at(x, y, 0) > threshold; }
};

// Two estimates, each with the variance of its mean. Images must have the same size and
// channels (throws an Error otherwise).
ComparisonResult compareImages(const Image& a, const Image& varianceA, const Image& b,
                               const Image& varianceB, double familyAlpha = 0.01,
                               double relativeFloor = 1e-6);
// An estimate with the variance of its mean against exact values.
ComparisonResult compareToExact(const Image& estimate, const Image& variance, const Image& exact,
                                double familyAlpha = 0.01, double relativeFloor = 1e-6);

// The two-sided standard normal critical value: P(|Z| > z) = level.
double twoSidedCriticalZ(double level);

}  // namespace lpvlab
