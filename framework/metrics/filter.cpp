#include "framework/metrics/filter.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <OpenImageIO/parallel.h>

namespace lpvlab {

namespace {

// The sample index for offset j outside [0, length): the nearest edge, or -1 for "none" (0).
int borderIndex(int j, int length, Border border) {
  if (j >= 0 && j < length) return j;
  return border == Border::zero ? -1 : std::clamp(j, 0, length - 1);
}

}  // namespace

// Rows are independent in each pass, so they run in parallel (OpenImageIO's thread pool). Both
// passes add whole shifted rows times a tap (the horizontal one shifting a copy of the row padded
// by the border rule), which reads memory in order and vectorises.
Plane convolveSeparable(const Plane& plane, const Taps& horizontal, const Taps& vertical,
                        Border border) {
  const int w = plane.width, h = plane.height;
  const int rx = int(horizontal.size() / 2), ry = int(vertical.size() / 2);
  Plane rows(w, h);
  OIIO::parallel_for(0, h, [&](int y) {
    std::vector<double> padded(std::size_t(w + 2 * rx), 0.0);
    const double* src = &plane.values[std::size_t(y) * w];
    for (int i = -rx; i < w + rx; ++i) {
      const int j = borderIndex(i, w, border);
      if (j >= 0) padded[i + rx] = src[j];
    }
    double* dst = &rows.values[std::size_t(y) * w];
    for (int k = 0; k <= 2 * rx; ++k) {
      const double tap = horizontal[k];
      for (int x = 0; x < w; ++x) dst[x] += tap * padded[x + k];
    }
  });
  Plane out(w, h);
  OIIO::parallel_for(0, h, [&](int y) {
    double* dst = &out.values[std::size_t(y) * w];
    for (int k = -ry; k <= ry; ++k) {
      const int j = borderIndex(y + k, h, border);
      if (j < 0) continue;
      const double* src = &rows.values[std::size_t(j) * w];
      const double tap = vertical[ry + k];
      for (int x = 0; x < w; ++x) dst[x] += tap * src[x];
    }
  });
  return out;
}

Taps gaussianTaps(double sigma, int radius) {
  Taps taps(2 * radius + 1);
  for (int k = -radius; k <= radius; ++k)
    taps[radius + k] = std::exp(-double(k) * k / (2.0 * sigma * sigma));
  return taps;
}

Taps normalised(Taps taps) {
  const double sum = std::accumulate(taps.begin(), taps.end(), 0.0);
  for (double& tap : taps) tap /= sum;
  return taps;
}

}  // namespace lpvlab
