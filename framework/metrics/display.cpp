#include "framework/metrics/display.h"

#include <algorithm>
#include <cmath>

namespace lpvlab {

double displayExposure(const Image& reference, const PixelMask& mask,
                       std::optional<double> chosen) {
  if (chosen) return *chosen;
  // middleGreyExposure takes a whole image; give it the covered pixels only, as a 1-row image.
  Image covered(int(mask.count), 1, 3);
  std::size_t next = 0;
  for (std::size_t p = 0; p < mask.covered.size(); ++p) {
    if (!mask.covers(p)) continue;
    std::copy_n(&reference.pixels[p * 3], 3, &covered.pixels[next * 3]);
    ++next;
  }
  return middleGreyExposure(covered);
}

Image toDisplay(const Image& rgb, double exposureStops) {
  const float scale = float(std::exp2(exposureStops));
  Image display = rgb;
  for (float& value : display.pixels) value = std::clamp(value * scale, 0.0f, 1.0f);
  return display;
}

float encodeSrgb(float linear) {
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float decodeSrgb(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace lpvlab
