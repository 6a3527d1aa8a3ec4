#pragma once
// Image metrics: how far a rendered image (test) is from a reference, over the pixels a mask
// covers. Both images are linear RGB radiance (HDR, any units); the mask is optional.
//
//   mae, rmse  mean |t - r| and sqrt(mean (t - r)^2) over covered pixels and the 3 channels
//   relMse     mean over covered pixels and channels of (t - r)^2 / (r^2 + relMseEpsilon)
//   psnr       10 log10(peak^2 / MSE), MSE = rmse^2; +inf when the images agree exactly
//   ssim       mean SSIM (Wang et al. 2004) over covered pixels, on display luminance (ssim.h)
//   flip       mean LDR-FLIP (Andersson et al. 2020) over covered pixels, of the display images
//              (flip.h)
//   hdrFlip    mean HDR-FLIP (Andersson et al. 2021) over covered pixels, of the linear images:
//              the largest LDR-FLIP over the exposures the reference spans, each tone-mapped
//              (hdr_flip.h)
//   blockNrmse the RMSE of 8 x 8-pixel block means over the reference's mean (block_error.h):
//              the low frequencies' error, blind to pixel noise of zero mean
//
// SSIM and FLIP are defined for displayed (LDR) images, so they see the images as shown on a
// screen: scaled by 2^exposureStops and clamped to [0, 1] per channel ("the display images",
// display.h). By default the exposure brings the reference's median luminance over the covered
// pixels to middle grey 0.18, the same rule as the PNGs lpvlab writes (middleGreyExposure), so
// the figures do not depend on the radiance units. That is one exposure and a clamp: what is
// brighter than white or darker than the display's black there is not seen. HDR-FLIP sees every
// exposure from the reference's brightest pixel to its median, so it sees those errors too.
//
// A mask is a 1-channel image of the same size: a pixel whose mask value is 0 is background and
// is left out of every figure (any other value includes it; values are not weights). Changing a
// background pixel of either image changes no figure.
//
// Every input pixel (background included) must be finite: a NaN or Inf is an Error naming the
// image, pixel and channel, never a silently skipped value.

#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include "framework/io/image.h"
#include "framework/metrics/hdr_flip.h"

namespace lpvlab {

struct MetricOptions {
  // Relative MSE's denominator is r^2 + relMseEpsilon, in squared radiance units: the epsilon
  // keeps near-black reference values from dominating (and from dividing by zero).
  double relMseEpsilon = 1e-2;
  // PSNR's peak signal. Unset: the reference's maximum over the covered pixels and channels
  // (the usual choice for HDR radiance, which has no fixed white). Must be positive.
  std::optional<double> psnrPeak;
  // The display exposure for SSIM and FLIP, in stops. Unset: log2(0.18 / median), the median
  // being the reference's Rec. 709 luminance over the covered non-black pixels (0 when there is
  // none).
  std::optional<double> exposureStops;
  // FLIP's observer: pixels per degree of visual angle. The default is FLIP's: a 0.7 m wide
  // 3840-pixel monitor seen from 0.7 m, 0.7 * 3840 / 0.7 * pi / 180 = 67.02 pixels per degree.
  double pixelsPerDegree = 0.7 * 3840.0 / 0.7 * 3.14159265358979323846 / 180.0;
  // HDR-FLIP's exposures. Unset: the range the reference implies (hdrFlipExposures).
  std::optional<HdrFlipExposures> hdrFlipExposures;
};

struct MetricSet {
  double mae = 0.0;
  double rmse = 0.0;
  double relMse = 0.0;
  double psnr = 0.0;        // dB; +inf for identical images
  double ssim = 0.0;        // in [-1, 1], 1 for identical images
  double flip = 0.0;        // in [0, 1], 0 for identical images
  double hdrFlip = 0.0;     // in [0, 1], 0 for identical images
  double blockNrmse = 0.0;  // unitless; +inf when the reference is black and the test is not
  std::int64_t pixels = 0;  // covered pixels

  // {"mae", "rmse", "rel_mse", "psnr", "ssim", "flip", "hdr_flip", "block_nrmse", "pixels"}.
  // JSON has no infinity, so an infinite PSNR (identical images) or block nRMSE is written "inf".
  nlohmann::json toJson() const;
};

// Per-pixel HDR-FLIP of the linear images, 1 channel in [0, 1]; 0 at background pixels; and
// the exposures it spanned.
struct HdrFlipMap {
  Image error;
  HdrFlipExposures exposures;
};

// Throws an Error when the images are not RGB, differ in size, hold a NaN or Inf, when the mask
// is not 1-channel of the same size or covers no pixel, or when the PSNR peak is not positive.
// `hdrFlipMap`, if given, receives the HDR-FLIP map behind metrics.hdrFlip (computed once).
MetricSet computeMetrics(const Image& test, const Image& reference, const Image* mask = nullptr,
                         const MetricOptions& options = {}, HdrFlipMap* hdrFlipMap = nullptr);

// Per-pixel LDR-FLIP of the display images, 1 channel in [0, 1]; 0 at background pixels.
Image flipErrorMap(const Image& test, const Image& reference, const Image* mask = nullptr,
                   const MetricOptions& options = {});

// Per-pixel HDR-FLIP of the linear images (HdrFlipMap, above).
HdrFlipMap hdrFlipErrorMap(const Image& test, const Image& reference, const Image* mask = nullptr,
                           const MetricOptions& options = {});

// The FLIP map in false colour for looking at: 3 channels in [0, 1], the per-pixel FLIP value
// through the magma ramp (black, purple, orange, pale yellow for 0 -> 1, the colour map FLIP's
// own tool uses); background pixels mid grey, which is on no point of the ramp. The values are
// linear, as writePng expects: writePng(path, map, 0.0f, false) stores magma's sRGB colours.
Image errorHeatMap(const Image& test, const Image& reference, const Image* mask = nullptr,
                   const MetricOptions& options = {});

// A one-channel image through the same magma ramp, `low` black to `high` pale yellow (values
// outside clamped to the ends), background pixels (mask 0) mid grey; linear values for writePng.
Image falseColour(const Image& values, float low, float high, const Image* mask = nullptr);

// `heat` with its colour bar: a strip along its right edge, after a gap of background grey, whose
// rows run through the ramp from its low end at the bottom to its high end at the top.
Image withColourBar(const Image& heat);

}  // namespace lpvlab
