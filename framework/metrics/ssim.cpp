#include "framework/metrics/ssim.h"

#include "framework/metrics/display.h"
#include "framework/metrics/filter.h"

namespace lpvlab {

namespace {

constexpr double kSigma = 1.5;
constexpr int kRadius = 5;           // 11 x 11
constexpr double kC1 = 0.01 * 0.01;  // (K1 L)^2, L = 1
constexpr double kC2 = 0.03 * 0.03;  // (K2 L)^2

// encodeSrgb(luminance) of each pixel, 0 at background (so it adds nothing to a window).
Plane maskedLuma(const Image& display, const PixelMask& mask) {
  Plane luma(display.width, display.height);
  for (std::size_t p = 0; p < luma.values.size(); ++p) {
    if (!mask.covers(p)) continue;
    const float* rgb = &display.pixels[p * 3];
    luma[p] = encodeSrgb(luminance(rgb[0], rgb[1], rgb[2]));
  }
  return luma;
}

Plane product(const Plane& a, const Plane& b) {
  Plane out(a.width, a.height);
  for (std::size_t p = 0; p < out.values.size(); ++p) out[p] = a[p] * b[p];
  return out;
}

}  // namespace

double meanSsim(const Image& testDisplay, const Image& referenceDisplay, const PixelMask& mask) {
  const Taps window = normalised(gaussianTaps(kSigma, kRadius));
  auto filter = [&](const Plane& plane) {
    return convolveSeparable(plane, window, window, Border::zero);
  };

  Plane coverage(mask.width, mask.height);
  for (std::size_t p = 0; p < coverage.values.size(); ++p) coverage[p] = mask.covered[p];
  const Plane x = maskedLuma(testDisplay, mask);
  const Plane y = maskedLuma(referenceDisplay, mask);

  // Window sums of the covered pixels' weights, values, squares and products; x and y are 0 at
  // background, so each sum counts covered pixels only.
  const Plane weight = filter(coverage);
  const Plane sumX = filter(x), sumY = filter(y);
  const Plane sumXX = filter(product(x, x)), sumYY = filter(product(y, y));
  const Plane sumXY = filter(product(x, y));

  double total = 0.0;
  for (std::size_t p = 0; p < coverage.values.size(); ++p) {
    if (!mask.covers(p)) continue;
    // weight[p] >= the window's centre tap, since p itself is covered.
    const double w = weight[p];
    const double muX = sumX[p] / w, muY = sumY[p] / w;
    const double varX = sumXX[p] / w - muX * muX;
    const double varY = sumYY[p] / w - muY * muY;
    const double covXY = sumXY[p] / w - muX * muY;
    total += (2.0 * muX * muY + kC1) * (2.0 * covXY + kC2) /
             ((muX * muX + muY * muY + kC1) * (varX + varY + kC2));
  }
  return total / double(mask.count);
}

}  // namespace lpvlab
