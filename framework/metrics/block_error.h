#pragma once
// The error of an image's low frequencies: block nRMSE. The covered pixels are averaged over
// blocks of `block` x `block` pixels (per channel; a block's mean over its covered pixels only,
// a block with none left out), and
//
//   block nRMSE = sqrt(mean over blocks and channels of (mean_t - mean_r)^2)
//                 / (mean over blocks and channels of mean_r)
//
// Pixel noise of zero mean within a block does not change it, while a wrong brightness or a
// misplaced gradient does: the error LPV's coarse grid makes, without the path tracer's noise
// (issue 38 reports LPV's error by it, 8 x 8 blocks). Normalised by the reference's mean, so it
// is unitless. A reference whose block means are all 0 gives 0 for an equal test, +inf otherwise.

#include "framework/io/image.h"
#include "framework/metrics/mask.h"

namespace lpvlab {

inline constexpr int kErrorBlockSize = 8;

// `test` and `reference` RGB of one size, `mask` as checkInputs made it.
double blockNrmse(const Image& test, const Image& reference, const PixelMask& mask,
                  int block = kErrorBlockSize);

}  // namespace lpvlab
