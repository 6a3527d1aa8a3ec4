#include "framework/metrics/hdr_flip.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/metrics/display.h"
#include "framework/metrics/flip.h"

namespace lpvlab {

namespace {

// t(x) = (a x^2 + b x) / (d x^2 + e x + f): Narkowicz's ACES fit, 0.6 x substituted for x.
constexpr double kA = 0.6 * 0.6 * 2.51, kB = 0.6 * 0.03;
constexpr double kD = 0.6 * 0.6 * 2.43, kE = 0.6 * 0.59, kF = 0.14;

// The value t maps to `target`: the larger root of (a - target d) x^2 + (b - target e) x
// - target f = 0. For target 0.85 the leading coefficient is negative and the product of the
// roots positive, so both roots are real and positive, and the larger one is on the curve's rise.
double toneMapInverse(double target) {
  const double a = kA - target * kD, b = kB - target * kE, c = -target * kF;
  const double half = -0.5 * b / a;
  const double spread = std::sqrt(half * half - c / a);
  return std::max(half - spread, half + spread);
}

// The median (the element at n/2 of the sorted values, as the reference code takes it).
double medianOf(std::vector<double> values) {
  const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

Image toneMapped(const Image& rgb, double exposureStops) {
  const double scale = std::exp2(exposureStops);
  Image out = rgb;
  for (float& value : out.pixels)
    value = float(std::clamp(acesToneMap(std::max(0.0, double(value) * scale)), 0.0, 1.0));
  return out;
}

void checkExposures(const HdrFlipExposures& e) {
  if (!std::isfinite(e.start) || !std::isfinite(e.stop) || e.start > e.stop || e.count < 2)
    throw Error("HDR-FLIP: exposures must be finite with start <= stop and count >= 2, got start " +
                std::to_string(e.start) + ", stop " + std::to_string(e.stop) + ", count " +
                std::to_string(e.count));
}

}  // namespace

double acesToneMap(double linear) {
  return (kA * linear * linear + kB * linear) / (kD * linear * linear + kE * linear + kF);
}

HdrFlipExposures hdrFlipExposures(const Image& reference, const PixelMask& mask) {
  std::vector<double> covered, lit;
  double largest = 0.0;
  for (std::size_t p = 0; p < mask.covered.size(); ++p) {
    if (!mask.covers(p)) continue;
    const float* rgb = &reference.pixels[p * 3];
    const double y = luminance(rgb[0], rgb[1], rgb[2]);
    covered.push_back(y);
    if (y > 0.0) lit.push_back(y);
    largest = std::max(largest, y);
  }
  if (lit.empty()) return {};  // a black reference: one exposure, 0 stops
  double median = medianOf(covered);
  if (!(median > 0.0)) median = medianOf(lit);
  const double x85 = toneMapInverse(0.85);
  HdrFlipExposures e;
  e.start = std::log2(x85 / largest);
  e.stop = std::log2(x85 / median);
  e.count = int(std::max(2.0, std::ceil(e.stop - e.start)));
  return e;
}

HdrFlipMaps hdrFlip(const Image& test, const Image& reference, const PixelMask& mask,
                    double pixelsPerDegree, const HdrFlipExposures& exposures) {
  checkExposures(exposures);
  const double step = (exposures.stop - exposures.start) / double(exposures.count - 1);
  std::vector<Plane> perExposure(std::size_t(exposures.count), Plane(0, 0));
  tbb::parallel_for(0, exposures.count, [&](int i) {
    const double stops = exposures.start + i * step;
    perExposure[std::size_t(i)] =
        ldrFlip(toneMapped(test, stops), toneMapped(reference, stops), mask, pixelsPerDegree);
  });
  // In exposure order, a later exposure replacing an earlier one only where strictly larger.
  HdrFlipMaps maps{Plane(mask.width, mask.height), Plane(mask.width, mask.height), exposures};
  for (int i = 0; i < exposures.count; ++i) {
    const Plane& flip = perExposure[std::size_t(i)];
    for (std::size_t p = 0; p < flip.values.size(); ++p)
      if (flip[p] > maps.error[p]) {
        maps.error[p] = flip[p];
        maps.exposure[p] = double(i) / double(exposures.count - 1);
      }
  }
  return maps;
}

}  // namespace lpvlab
