#pragma once
// What a run writes about itself, shared by static runs (run.h) and sequences (sequence.h): the
// checks of its images, its comparison with the reference, and the description of the run that
// opens its manifest.

#include <nlohmann/json.hpp>
#include <map>
#include <string>
#include <vector>

#include "framework/experiment/experiment.h"
#include "framework/gl/context.h"
#include "framework/io/image.h"
#include "framework/pipeline/pipeline.h"
#include "framework/reference/reference_cache.h"

namespace lpvlab {

// Throws an Error, before anything is written, if any output holds NaN or Inf.
void requireFiniteImages(const std::vector<NamedImage>& aovs);

// What a finished run's outputs and manifest show that its exit code cannot: everything black
// (no light reached anything: black or zero lights, degenerate geometry), indirect light zero
// everywhere while direct light is not, an indirect method's solve that did not converge. Each a
// sentence for stderr and the manifest's "warnings" (which summary.csv and the report carry).
std::vector<std::string> resultWarnings(const std::vector<NamedImage>& aovs,
                                        const nlohmann::json& manifest);

// The pixels where the camera sees a surface (depth 0 marks the background).
Image coverageMask(const Image& depth);

// How the run's outputs compare with the reference's, per configured pair (run output, reference
// output), over the pixels the camera sees: the metrics (framework/metrics/metrics.h), per region
// too, the means and their ratio (of every pixel and channel, imageMean), the reference mean's
// relative standard error (from its pixels' variances, each pixel's channels taken as fully
// correlated, which bounds it from above), and a per-pixel z-test against the reference's variance at a
// Sidak-corrected 1% family level (how many pixel channels the reference's noise can't explain).
nlohmann::json compareWithReference(const std::vector<NamedImage>& run, const Reference& ref,
                                    const Image& mask, const ComparisonSettings& settings);

// The manifest's description of the run: versions, configuration, scene, host, libraries, where
// the kernels ran, memory and work per frame, and what the method says of itself given each
// stage's median time (IndirectMethod::describe: LPV's grids and propagation throughput).
nlohmann::json describeRun(const Experiment& experiment, const GlContext& context,
                           const Pipeline& pipeline, const std::string& sceneHash,
                           const std::map<std::string, double>& medianStageMs);


}  // namespace lpvlab
