// errorHeatMap: the FLIP map through a false-colour ramp.

#include "framework/metrics/metrics.h"

#include <algorithm>
#include <array>

#include "framework/metrics/display.h"

namespace lpvlab {

namespace {

// Matplotlib's magma colour map (van der Walt and Smith, CC0) sampled at 0, 1/16, ..., 1, in
// sRGB; linear interpolation between samples stays within 3.4/255 of the full 256-entry map.
constexpr std::array<std::array<float, 3>, 17> kMagma = {{
    {0.0015f, 0.0005f, 0.0139f},
    {0.0396f, 0.0311f, 0.1335f},
    {0.1131f, 0.0655f, 0.2768f},
    {0.2117f, 0.0620f, 0.4186f},
    {0.3167f, 0.0717f, 0.4854f},
    {0.4147f, 0.1104f, 0.5047f},
    {0.5128f, 0.1482f, 0.5076f},
    {0.6136f, 0.1818f, 0.4985f},
    {0.7164f, 0.2150f, 0.4753f},
    {0.8169f, 0.2559f, 0.4365f},
    {0.9043f, 0.3196f, 0.3881f},
    {0.9609f, 0.4183f, 0.3596f},
    {0.9867f, 0.5356f, 0.3822f},
    {0.9961f, 0.6537f, 0.4462f},
    {0.9969f, 0.7696f, 0.5349f},
    {0.9924f, 0.8843f, 0.6401f},
    {0.9871f, 0.9914f, 0.7495f},
}};

// Background: sRGB 0.5 grey.
constexpr float kBackgroundSrgb = 0.5f;

}  // namespace

Image errorHeatMap(const Image& test, const Image& reference, const Image* mask,
                   const MetricOptions& options) {
  const Image flip = flipErrorMap(test, reference, mask, options);  // checks the inputs
  Image heat(flip.width, flip.height, 3);
  for (std::size_t p = 0; p < flip.pixels.size(); ++p) {
    std::array<float, 3> srgb;
    if (!mask || mask->pixels[p] != 0.0f) {
      // FLIP is in [0, 1]; the clamp only keeps a rounding excess from reading past the table.
      const float t = std::clamp(flip.pixels[p], 0.0f, 1.0f) * float(kMagma.size() - 1);
      const std::size_t i = std::min(std::size_t(t), kMagma.size() - 2);
      const float f = t - float(i);
      for (int c = 0; c < 3; ++c) srgb[c] = kMagma[i][c] + f * (kMagma[i + 1][c] - kMagma[i][c]);
    } else {
      srgb.fill(kBackgroundSrgb);
    }
    // Linear values, so that writePng's sRGB encoding stores the colour map's own values.
    for (int c = 0; c < 3; ++c) heat.pixels[p * 3 + c] = decodeSrgb(srgb[c]);
  }
  return heat;
}

}  // namespace lpvlab
