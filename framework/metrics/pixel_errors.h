#pragma once
// The per-value error figures: MAE, RMSE, relative MSE and PSNR over the covered pixels and the
// three channels (definitions in metrics.h).

#include "framework/io/image.h"
#include "framework/metrics/mask.h"
#include "framework/metrics/metrics.h"

namespace lpvlab {

struct PixelErrors {
  double mae = 0.0, rmse = 0.0, relMse = 0.0, psnr = 0.0;
};

PixelErrors pixelErrors(const Image& test, const Image& reference, const PixelMask& mask,
                        const MetricOptions& options);

}  // namespace lpvlab
