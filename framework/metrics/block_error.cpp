#include "framework/metrics/block_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lpvlab {

double blockNrmse(const Image& test, const Image& reference, const PixelMask& mask, int block) {
  double squares = 0.0, referenceSum = 0.0;
  long long values = 0;  // blocks with a covered pixel, times 3 channels
  for (int by = 0; by < reference.height; by += block)
    for (int bx = 0; bx < reference.width; bx += block) {
      double t[3] = {0.0, 0.0, 0.0}, r[3] = {0.0, 0.0, 0.0};
      long long covered = 0;
      for (int y = by; y < std::min(by + block, reference.height); ++y)
        for (int x = bx; x < std::min(bx + block, reference.width); ++x) {
          const std::size_t p = std::size_t(y) * reference.width + x;
          if (!mask.covers(p)) continue;
          ++covered;
          for (int c = 0; c < 3; ++c) {
            t[c] += test.pixels[p * 3 + c];
            r[c] += reference.pixels[p * 3 + c];
          }
        }
      if (covered == 0) continue;
      for (int c = 0; c < 3; ++c) {
        const double difference = (t[c] - r[c]) / double(covered);
        squares += difference * difference;
        referenceSum += r[c] / double(covered);
        ++values;
      }
    }
  if (values == 0) return 0.0;
  const double rms = std::sqrt(squares / double(values));
  const double mean = referenceSum / double(values);
  if (mean == 0.0) return rms == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return rms / std::abs(mean);
}

}  // namespace lpvlab
