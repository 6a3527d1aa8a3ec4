#pragma once
// The display images SSIM and FLIP compare: linear RGB scaled by 2^exposure and clamped to
// [0, 1] per channel, i.e. what an sRGB screen shows of an HDR image at that exposure (negative
// values, SH ringing, show as black).

#include <optional>

#include "framework/io/image.h"
#include "framework/metrics/mask.h"

namespace lpvlab {

// `chosen` when set; else the stops that bring the median Rec. 709 luminance of the reference's
// covered non-black pixels to middle grey 0.18 (lpvlab's PNG rule, middleGreyExposure); 0 when
// every covered pixel is black.
double displayExposure(const Image& reference, const PixelMask& mask, std::optional<double> chosen);

// clamp(2^exposureStops * value, 0, 1) for every channel; same layout as `rgb`.
Image toDisplay(const Image& rgb, double exposureStops);

// Rec. 709 / sRGB luminance of linear RGB.
inline float luminance(float r, float g, float b) {
  return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

// The sRGB transfer function (IEC 61966-2-1), linear [0, 1] -> encoded [0, 1], and its inverse.
float encodeSrgb(float linear);
float decodeSrgb(float encoded);

}  // namespace lpvlab
