#pragma once
// LDR-FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom, Fairchild 2020, "FLIP: A
// Difference Evaluator for Alternating Images", HPG 2020), constants as in the paper and
// NVIDIA's reference code. Per pixel, of two display images (linear RGB in [0, 1]):
//
// Colour pipeline
//  1. linear RGB -> XYZ -> YCxCz (flip_color.h).
//  2. Each channel filtered by its contrast sensitivity function, sampled at 1/ppd degrees:
//       s(r) = a1 sqrt(pi/b1) exp(-pi^2 r^2 / b1) + a2 sqrt(pi/b2) exp(-pi^2 r^2 / b2),
//     r in degrees, normalised to sum 1 over a (2R+1)^2 square, R = ceil(3 sqrt(0.04 / (2 pi^2))
//     ppd) for all three (0.04 the widest b):
//       achromatic Y:  a1 = 1,    b1 = 0.0047, a2 = 0
//       red-green Cx:  a1 = 1,    b1 = 0.0053, a2 = 0
//       blue-yellow Cz: a1 = 34.1, b1 = 0.04,  a2 = 13.5, b2 = 0.025
//     Border pixels are replicated. Each Gaussian is separable, so the filter runs as one (two
//     for Cz) separable pass with the same sums as the 2D kernel.
//  3. Back to linear RGB, clamped to [0, 1], then XYZ -> L*a*b* -> Hunt-adjusted (a*, b* times
//     0.01 L*).
//  4. HyAB distance d between test and reference; with qc = 0.7 and cmax = HyAB(green, blue)^qc
//     (Hunt-adjusted L*a*b* of linear RGB (0,1,0) and (0,0,1), the largest difference in the
//     gamut), pc = 0.4, pt = 0.95:
//       dEc = pt / (pc cmax) * d^qc                                 for d^qc < pc cmax
//       dEc = pt + (d^qc - pc cmax) / (cmax - pc cmax) * (1 - pt)   otherwise
//     so the smaller 40% of the range takes 95% of [0, 1].
// Feature pipeline, on the unfiltered luminance Y (XYZ's Y, in [0, 1]):
//  5. Gaussian of standard deviation sd = 0.5 w ppd pixels, w = 0.082 degrees (the peak-to-trough
//     width of human edge detectors), radius ceil(3 sd); edge filter its first derivative -x g,
//     point filter its second derivative (x^2 / sd^2 - 1) g, each with positive weights scaled
//     to sum 1 and negative ones to sum -1, applied along x and along y (the other axis smoothed
//     by the Gaussian normalised to 1); |edge| and |point| the norms of the (x, y) responses.
//  6. dEf = (max(| |edge_r| - |edge_t| |, | |point_r| - |point_t| |) / sqrt(2))^qf, qf = 0.5.
// Combination
//  7. FLIP = dEc^(1 - dEf), in [0, 1]: feature differences raise the colour error towards 1.
//
// Background pixels are set to black in both display images before filtering, so their content
// cannot reach the covered pixels through the filters (the filters are not averages everywhere,
// so they cannot be renormalised over covered pixels as SSIM's window is); their FLIP is 0.

#include "framework/io/image.h"
#include "framework/metrics/filter.h"
#include "framework/metrics/mask.h"

namespace lpvlab {

Plane ldrFlip(const Image& testDisplay, const Image& referenceDisplay, const PixelMask& mask,
              double pixelsPerDegree);

}  // namespace lpvlab
