#pragma once
// Planes (one value per pixel, in double so that SSIM's E[x^2] - E[x]^2 does not lose its
// variance to rounding) and their separable convolution, the one filtering step SSIM's windows
// and FLIP's contrast-sensitivity and feature filters share.

#include <cstddef>
#include <vector>

namespace lpvlab {

struct Plane {
  int width = 0;
  int height = 0;
  std::vector<double> values;  // row-major, top row first

  Plane(int w, int h) : width(w), height(h), values(std::size_t(w) * h, 0.0) {}
  double& operator[](std::size_t pixel) { return values[pixel]; }
  double operator[](std::size_t pixel) const { return values[pixel]; }
};

// Odd-length taps, centred: taps[radius + k] weighs the sample at offset k.
using Taps = std::vector<double>;

// Outside the image: the nearest edge pixel (as FLIP's reference code, which replicates the
// border), or 0 (SSIM's masked windows, which then renormalise by the filtered mask).
enum class Border { replicate, zero };

// out(x, y) = sum_{i,j} horizontal[i] vertical[j] in(x + i - r, y + j - r).
Plane convolveSeparable(const Plane& plane, const Taps& horizontal, const Taps& vertical,
                        Border border);

// exp(-k^2 / (2 sigma^2)) for k = -radius..radius, not normalised.
Taps gaussianTaps(double sigma, int radius);

// taps / sum(taps).
Taps normalised(Taps taps);

}  // namespace lpvlab
