#include "framework/metrics/pixel_errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

constexpr const char* kWhere = "computeMetrics";

// A float RGB ImageBuf of `image` with the background set to 0.
OIIO::ImageBuf coveredBuffer(const Image& image, const PixelMask& mask) {
  OIIO::ImageBuf buffer(OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT));
  std::vector<float> values = image.pixels;
  for (std::size_t p = 0; p < mask.covered.size(); ++p)
    if (!mask.covers(p)) std::fill_n(&values[p * 3], 3, 0.0f);
  buffer.set_pixels(buffer.roi(), OIIO::TypeDesc::FLOAT, values.data());
  return buffer;
}

double psnrPeak(const Image& reference, const PixelMask& mask, const MetricOptions& options) {
  double peak = -std::numeric_limits<double>::infinity();
  if (options.psnrPeak) {
    peak = *options.psnrPeak;
  } else {
    for (std::size_t p = 0; p < mask.covered.size(); ++p)
      if (mask.covers(p))
        for (int c = 0; c < 3; ++c) peak = std::max(peak, double(reference.pixels[p * 3 + c]));
  }
  if (!(peak > 0.0) || !std::isfinite(peak))
    throwAt(kWhere, "the PSNR peak is " + std::to_string(peak) +
                        (options.psnrPeak ? " (MetricOptions::psnrPeak)"
                                          : " (the reference's maximum over the covered pixels)") +
                        "; it must be positive and finite");
  return peak;
}

}  // namespace

PixelErrors pixelErrors(const Image& test, const Image& reference, const PixelMask& mask,
                        const MetricOptions& options) {
  if (!(options.relMseEpsilon > 0.0) || !std::isfinite(options.relMseEpsilon))
    throwAt(kWhere, "MetricOptions::relMseEpsilon is " + std::to_string(options.relMseEpsilon) +
                        "; it must be positive and finite");
  PixelErrors errors;

  // OIIO's compare gives the mean absolute and RMS error over every value of the images. With a
  // mask, the background is zeroed in both (an error of exactly 0 there) and the means are
  // rescaled from all values to the covered ones: mean_covered = mean_all * all / covered.
  const OIIO::ImageBuf testBuffer = coveredBuffer(test, mask);
  const OIIO::ImageBuf referenceBuffer = coveredBuffer(reference, mask);
  // The thresholds only count values differing by more; none is wanted (compare reports
  // failed values as an error), so they are infinite.
  const float noThreshold = std::numeric_limits<float>::infinity();
  const OIIO::ImageBufAlgo::CompareResults compared =
      OIIO::ImageBufAlgo::compare(testBuffer, referenceBuffer, noThreshold, noThreshold);
  if (compared.error)
    throwAt(kWhere,
            "OpenImageIO's compare failed: " + testBuffer.geterror() + referenceBuffer.geterror());
  const double share = double(mask.covered.size()) / double(mask.count);
  errors.mae = compared.meanerror * share;
  errors.rmse = compared.rms_error * std::sqrt(share);

  // OIIO has no relative MSE: (t - r)^2 / (r^2 + epsilon), averaged here.
  double relative = 0.0;
  for (std::size_t p = 0; p < mask.covered.size(); ++p) {
    if (!mask.covers(p)) continue;
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[p * 3 + c];
      const double d = double(test.pixels[p * 3 + c]) - r;
      relative += d * d / (r * r + options.relMseEpsilon);
    }
  }
  errors.relMse = relative / (3.0 * double(mask.count));

  // OIIO's PSNR assumes a peak of 1; this one uses the chosen peak. MSE = 0: +inf.
  const double peak = psnrPeak(reference, mask, options);
  errors.psnr = errors.rmse == 0.0 ? std::numeric_limits<double>::infinity()
                                   : 20.0 * std::log10(peak / errors.rmse);
  return errors;
}

}  // namespace lpvlab
