#include "framework/metrics/metrics.h"

#include <cmath>

#include "framework/metrics/block_error.h"
#include "framework/metrics/display.h"
#include "framework/metrics/flip.h"
#include "framework/metrics/mask.h"
#include "framework/metrics/pixel_errors.h"
#include "framework/metrics/ssim.h"

namespace lpvlab {

namespace {

// Both display images, at the exposure the options choose or the reference implies.
struct DisplayPair {
  Image test, reference;
};

DisplayPair displayPair(const Image& test, const Image& reference, const PixelMask& mask,
                        const MetricOptions& options) {
  const double stops = displayExposure(reference, mask, options.exposureStops);
  return {toDisplay(test, stops), toDisplay(reference, stops)};
}

// HDR-FLIP at the options' exposures, or the reference's range.
HdrFlipMaps hdrFlipOf(const Image& test, const Image& reference, const PixelMask& mask,
                      const MetricOptions& options) {
  return hdrFlip(test, reference, mask, options.pixelsPerDegree,
                 options.hdrFlipExposures ? *options.hdrFlipExposures
                                          : hdrFlipExposures(reference, mask));
}

// A map's mean over the covered pixels (the map is 0 at background).
double coveredMean(const Plane& map, const PixelMask& mask) {
  double sum = 0.0;
  for (std::size_t p = 0; p < map.values.size(); ++p) sum += map[p];
  return sum / double(mask.count);
}

Image toImage(const Plane& plane) {
  Image image(plane.width, plane.height, 1);
  for (std::size_t p = 0; p < plane.values.size(); ++p) image.pixels[p] = float(plane[p]);
  return image;
}

}  // namespace

nlohmann::json MetricSet::toJson() const {
  return {{"mae", mae},
          {"rmse", rmse},
          {"rel_mse", relMse},
          {"psnr", std::isinf(psnr) ? nlohmann::json("inf") : nlohmann::json(psnr)},
          {"ssim", ssim},
          {"flip", flip},
          {"hdr_flip", hdrFlip},
          {"block_nrmse", std::isinf(blockNrmse) ? nlohmann::json("inf") : nlohmann::json(blockNrmse)},
          {"pixels", pixels}};
}

MetricSet computeMetrics(const Image& test, const Image& reference, const Image* mask,
                         const MetricOptions& options, HdrFlipMap* hdrFlipMap) {
  const PixelMask covered = checkInputs("computeMetrics", test, reference, mask);
  const PixelErrors errors = pixelErrors(test, reference, covered, options);
  const DisplayPair display = displayPair(test, reference, covered, options);

  MetricSet metrics;
  metrics.mae = errors.mae;
  metrics.rmse = errors.rmse;
  metrics.relMse = errors.relMse;
  metrics.blockNrmse = blockNrmse(test, reference, covered);
  metrics.psnr = errors.psnr;
  metrics.ssim = meanSsim(display.test, display.reference, covered);
  metrics.flip = coveredMean(
      ldrFlip(display.test, display.reference, covered, options.pixelsPerDegree), covered);
  const HdrFlipMaps hdr = hdrFlipOf(test, reference, covered, options);
  metrics.hdrFlip = coveredMean(hdr.error, covered);
  if (hdrFlipMap) *hdrFlipMap = {toImage(hdr.error), hdr.exposures};
  metrics.pixels = covered.count;
  return metrics;
}

Image flipErrorMap(const Image& test, const Image& reference, const Image* mask,
                   const MetricOptions& options) {
  const PixelMask covered = checkInputs("flipErrorMap", test, reference, mask);
  const DisplayPair display = displayPair(test, reference, covered, options);
  return toImage(ldrFlip(display.test, display.reference, covered, options.pixelsPerDegree));
}

HdrFlipMap hdrFlipErrorMap(const Image& test, const Image& reference, const Image* mask,
                           const MetricOptions& options) {
  const PixelMask covered = checkInputs("hdrFlipErrorMap", test, reference, mask);
  const HdrFlipMaps maps = hdrFlipOf(test, reference, covered, options);
  return {toImage(maps.error), maps.exposures};
}

}  // namespace lpvlab
