#pragma once
// HDR-FLIP (Andersson, Nilsson, Shirley, Akenine-Moller 2021, "Visualizing Errors in Rendered High
// Dynamic Range Images", Eurographics short papers), as NVIDIA's reference code computes it: the
// per-pixel maximum of LDR-FLIP (flip.h) over a range of exposures, each image tone-mapped by
// the same curve before it is compared. Where LDR-FLIP sees one exposure and a clamp (so a
// highlight's error vanishes in white, a shadow's in black), HDR-FLIP sees every exposure at
// which a viewer could look at the image.
//
// Per exposure e (stops), both images (linear RGB, any units):
//   1. scaled by 2^e;
//   2. tone-mapped per channel by Narkowicz's fit of the ACES curve with its 0.6 pre-exposure
//      taken out:  t(x) = (0.6^2 2.51 x^2 + 0.6 0.03 x) / (0.6^2 2.43 x^2 + 0.6 0.59 x + 0.14);
//   3. clamped to [0, 1] and compared by LDR-FLIP.
// The exposures, unless given: `count` of them evenly spaced from `start` to `stop`,
//   start = log2(x85 / Ymax), stop = log2(x85 / Ymedian), count = max(2, ceil(stop - start)),
// where x85 is the value t maps to 0.85 (the larger root of t(x) = 0.85), and Ymax and Ymedian
// are the largest and the median Rec. 709 luminance of the reference's covered pixels: at
// `start` the brightest pixel shows at 0.85, at `stop` the median pixel does.
//
// Where the reference code's rule breaks down:
//   - a median luminance of 0 (more than half the covered pixels black, as in an `indirect` AOV
//     with much shadow) would make `stop` infinite: the median of the non-black covered pixels is
//     used instead (the same rule as the display exposure of display.h);
//   - a black reference has no range: one exposure, 0 stops (count 2, both at 0, as the formula
//     gives for an empty range).
// The reference code takes the median over every pixel; here only covered pixels (the mask)
// count, as in every other metric. With every pixel covered and a median above 0 the two agree.

#include <vector>

#include "framework/io/image.h"
#include "framework/metrics/filter.h"
#include "framework/metrics/mask.h"

namespace lpvlab {

struct HdrFlipExposures {
  double start = 0.0;  // stops
  double stop = 0.0;   // stops, >= start
  int count = 2;       // >= 2, evenly spaced, both ends included
};

struct HdrFlipMaps {
  Plane error;     // per pixel, the largest LDR-FLIP over the exposures, in [0, 1]; 0 at background
  // Per pixel, the index of that exposure over count - 1, in [0, 1]; the first one on ties.
  Plane exposure;
  HdrFlipExposures exposures;
};

// Narkowicz's ACES fit without its pre-exposure (step 2 above), of one linear value >= 0.
double acesToneMap(double linear);

// The exposure range the reference implies (above), over its covered pixels.
HdrFlipExposures hdrFlipExposures(const Image& reference, const PixelMask& mask);

// HDR-FLIP of `test` against `reference` (linear RGB, HDR) at `exposures`. The exposures run in
// parallel; the result does not depend on how many threads ran them.
HdrFlipMaps hdrFlip(const Image& test, const Image& reference, const PixelMask& mask,
                    double pixelsPerDegree, const HdrFlipExposures& exposures);

}  // namespace lpvlab
