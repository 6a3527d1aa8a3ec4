#pragma once
// lpvlab explain's error budget (docs/explain.md): LPV's error against the reference split by
// stage, from the frame rendered with one stage at a time replaced by its exact counterpart. The
// images form a chain, each one stage more exact than the one before:
//
//   method          the method's own indirect light (LPV, as configured)
//   grid            the exact grid (exact_grid.h) rendered by the method's rendering: propagation
//                   replaced (with visibility from the cells when LPV's own propagation blocks
//                   light by a GV, else without)
//   gather          the RSM's VPLs gathered exactly at each pixel, with the same visibility:
//                   the grid and its interpolation replaced
//   gather_visible  the same with exact visibility (only when the chain's gather has none):
//                   occlusion replaced
//   reference       the path tracer's one-bounce light (the pair's reference AOV)
//
// A stage's term is how much the error falls when it is replaced: e(before) - e(after), so the
// terms telescope to e(method); injection's term is what is left, e(gather_visible): representing
// the light by the RSM's VPLs (plus the reference's own noise). The same chain in the ratio of
// the means gives each stage's factor of the brightness, and leakage is the exact gather without
// visibility over the one with it. Each term also has its direct figure, the error of the image
// before against the one after (the stage's own error, blind to what the stages after it add).

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/io/image.h"

namespace lpvlab {

// Errors of one image against another over the covered pixels.
struct ErrorFigures {
  double blockNrmse = 0.0;  // metrics.h's: 8 x 8 block means, over the reference's mean
  double rmse = 0.0;        // W/(m^2 sr)
  double meanRatio = 0.0;   // mean(test) / mean(reference); 0 when the reference is black
};
ErrorFigures errorFigures(const Image& test, const Image& reference, const Image& mask);
nlohmann::json toJson(const ErrorFigures& figures);

// The indirect images of one explained frame (RGB, top row first, one size).
struct ExplainImages {
  Image method;  // the method's own indirect image
  Image grid, gridVisible;      // exact grids without / with visibility from the cells
  Image gather, gatherVisible;  // exact gathers without / with visibility
  // The oracles' own noise as block nRMSE against the reference's mean (from two independent VPL
  // draws: zero when every RSM texel was a VPL), by image name.
  std::map<std::string, double> noise;
};

// The reference's own noise in block nRMSE's terms: the root of the mean, over 8 x 8 blocks and
// channels, of the variance of a block's mean (its covered pixels' variances of their means over
// their count squared: independent pixels), over the mean of the block means. An exact image's
// block nRMSE against the reference is about this; the injection term holds it.
double referenceNoiseBlockNrmse(const Image& reference, const Image& varianceOfMean, const Image& mask);

// The budget of one pair (the run's AOV and the reference's): `reference` is the reference's AOV,
// `direct` what the run adds to the indirect light for that AOV (the direct image for
// "combined", null for "indirect"). `gridBlocksLight`: LPV's propagation blocks light (a GV).
nlohmann::json errorBudget(const ExplainImages& images, const Image* direct, const Image& reference,
                           const Image& mask, bool gridBlocksLight);

}  // namespace lpvlab
