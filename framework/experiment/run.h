#pragma once
// Running an experiment: warm-up frames (llvmpipe compiles shaders on first use), then timed
// repeats, then the outputs of the last frame written into the run's own directory:
//   images.exr     every AOV (direct, indirect, combined, albedo, normal, depth) as float channels
//   combined.png   the combined image, tone-mapped, for looking
//   manifest.json  the resolved configuration, scene hash, library versions, git revision, host,
//                  GL renderer, per-stage timings (median and spread over repeats), memory, and
//                  the injection flux balance
// Every file is written to a temporary name and renamed; the manifest is written last, so a
// directory without one is an interrupted run.

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "framework/core/stats.h"
#include "framework/gl/context.h"
#include "framework/experiment/experiment.h"

namespace lpvlab {

struct TimingReport {
  int warmupFrames = 0;
  int repeats = 0;
  // Per stage, plus "total" (their sum): stageMs by each stage's clock, wallMs by the steady one.
  std::map<std::string, Summary> stageMs, wallMs;
  std::map<std::string, std::vector<double>> stageSamples, wallSamples;  // per repeat, in order
  // Per stage: kGlTimerQuery or kCpuWallClock (pipeline.h); "total": theirs when all agree, else
  // "mixed".
  std::map<std::string, std::string> clock;
  // The stages in the order the frames ran them (the maps above are sorted by name), then "total".
  std::vector<std::string> order;
  nlohmann::json toJson() const;
};

// The timings of `frames` (in order) summarised per stage, after `warmup` untimed frames.
TimingReport timingReport(const std::vector<FrameTimes>& frames, int warmup);
// A stage's median time by its clock (ms), 0 when the run has no such stage (another indirect
// method has no "propagation").
double medianStageMs(const TimingReport& timing, const std::string& stage);
// Renders `warmup` untimed frames and `repeats` timed ones.
TimingReport measureFrames(Pipeline& pipeline, int warmup, int repeats);

// Builds the pipeline for `experiment` (on the current GL context) and runs it into `outDir`;
// returns the manifest. Throws an Error if any output holds NaN or Inf. An animated experiment
// renders its sequence (sequence.h).
nlohmann::json runExperiment(Experiment& experiment, const GlContext& context,
                             const std::string& outDir);

}  // namespace lpvlab
