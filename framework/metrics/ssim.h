#pragma once
// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, "Image quality assessment: from error visibility
// to structural similarity", IEEE TIP 13(4)) on the display images' luminance.
//
// The compared value of a pixel is encodeSrgb(Y), Y the Rec. 709 luminance of the display
// (exposed, clamped) linear RGB: a [0, 1] value on the gamma-encoded scale of the 8-bit images
// SSIM was designed for, so the dynamic range is L = 1. Constants as in the paper:
//   window   Gaussian, sigma = 1.5 pixels, 11 x 11 (radius 5), weights summing to 1
//   C1 = (K1 L)^2, K1 = 0.01;  C2 = (K2 L)^2, K2 = 0.03
//   SSIM(p) = (2 mu_x mu_y + C1) (2 sigma_xy + C2)
//             / ((mu_x^2 + mu_y^2 + C1) (sigma_x^2 + sigma_y^2 + C2))
// with mu, sigma^2 and sigma_xy the window-weighted means, variances and covariance around p.
// The window uses covered pixels only: the weights of background pixels and of positions
// outside the image are dropped and the rest renormalised to sum 1 (Wang's code instead drops
// the pixels whose window crosses the border, which leaves no value on images under 11 pixels).
// The result is the mean of SSIM(p) over the covered pixels.

#include "framework/io/image.h"
#include "framework/metrics/mask.h"

namespace lpvlab {

double meanSsim(const Image& testDisplay, const Image& referenceDisplay, const PixelMask& mask);

}  // namespace lpvlab
