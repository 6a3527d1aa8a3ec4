#pragma once
// Running an experiment: warm-up frames (llvmpipe compiles shaders on first use), then timed
// repeats, then the outputs of the last frame written into the run's own directory:
//   images.exr     every AOV (direct, indirect, combined, albedo, normal, depth) as float channels
//   combined.png   the combined image, tone-mapped, for looking
//   manifest.json  the resolved configuration, scene hash, library versions, git revision, host,
//                  GL renderer, per-stage timings (median and spread over repeats), memory, and
//                  the injection flux balance
//   grid.npy, grid.json  with [output] dump_grid: the method's light grid (writeGridDump)
// Every file is written to a temporary name and renamed; the manifest is written last, so a
// directory without one is an interrupted run.

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "framework/gl/context.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/timing.h"

namespace lpvlab {

// Builds the pipeline for `experiment` (on the current GL context) and runs it into `outDir`;
// returns the manifest. Throws an Error if any output holds NaN or Inf. An animated experiment
// renders its sequence (sequence.h).
nlohmann::json runExperiment(Experiment& experiment, const GlContext& context,
                             const std::string& outDir);

// Writes `dump` into `outDir` as <stem>.npy (numpy.load reads it) and <stem>.json (its axes,
// shape, units, basis and where each level's cells are); returns the manifest's outputs.grid entry.
nlohmann::json writeGridDump(const GridDump& dump, const std::string& outDir,
                             const std::string& stem = "grid");

}  // namespace lpvlab
