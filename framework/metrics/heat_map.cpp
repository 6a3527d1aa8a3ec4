// errorHeatMap: the FLIP map through a false-colour ramp; falseColour and withColourBar, the ramp
// for any scalar image and its key.

#include "framework/metrics/metrics.h"

#include <algorithm>
#include <array>
#include <string>

#include "framework/core/error.h"
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

namespace {

// The magma colour at t in [0, 1] (clamped), as linear values for writePng.
std::array<float, 3> magmaLinear(float t) {
  t = std::clamp(t, 0.0f, 1.0f) * float(kMagma.size() - 1);
  const std::size_t i = std::min(std::size_t(t), kMagma.size() - 2);
  const float f = t - float(i);
  std::array<float, 3> linear;
  for (int c = 0; c < 3; ++c) linear[c] = decodeSrgb(kMagma[i][c] + f * (kMagma[i + 1][c] - kMagma[i][c]));
  return linear;
}

}  // namespace

Image falseColour(const Image& values, float low, float high, const Image* mask) {
  if (values.channels != 1) throw Error("falseColour: the image has " + std::to_string(values.channels) + " channels, not 1");
  if (!(high > low)) throw Error("falseColour: the range [" + std::to_string(low) + ", " + std::to_string(high) + "] is empty");
  Image out(values.width, values.height, 3);
  const float background = decodeSrgb(kBackgroundSrgb);
  for (std::size_t p = 0; p < values.pixels.size(); ++p) {
    std::array<float, 3> linear;
    if (!mask || mask->pixels[p] != 0.0f)
      linear = magmaLinear((values.pixels[p] - low) / (high - low));
    else
      linear.fill(background);
    for (int c = 0; c < 3; ++c) out.pixels[p * 3 + c] = linear[c];
  }
  return out;
}

Image withColourBar(const Image& heat) {
  const int bar = std::max(8, heat.width / 24), gap = std::max(2, bar / 4);
  Image out(heat.width + gap + bar, heat.height, 3, decodeSrgb(kBackgroundSrgb));
  for (int y = 0; y < heat.height; ++y) {
    for (int x = 0; x < heat.width; ++x)
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = heat.at(x, y, c);
    // Top row first: the top of the bar is the range's high end.
    const std::array<float, 3> linear =
        magmaLinear(heat.height > 1 ? 1.0f - float(y) / float(heat.height - 1) : 1.0f);
    for (int x = heat.width + gap; x < out.width; ++x)
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = linear[c];
  }
  return out;
}

Image errorHeatMap(const Image& test, const Image& reference, const Image* mask,
                   const MetricOptions& options) {
  // FLIP is in [0, 1]; the clamp keeps a rounding excess on the ramp.
  return falseColour(flipErrorMap(test, reference, mask, options), 0.0f, 1.0f, mask);
}

}  // namespace lpvlab
