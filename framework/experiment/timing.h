#pragma once
// A run's timings: each frame's per-stage times (Pipeline::renderFrame) summarised over the
// timed frames, per stage by its own clock (pipeline.h: GL timer queries, or the wall clock for a
// stage on the CPU backend) and by the steady clock, with the order the stages ran in.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/stats.h"
#include "framework/pipeline/pipeline.h"

namespace lpvlab {

struct TimingReport {
  int warmupFrames = 0;
  int repeats = 0;
  // Per stage, plus the sums "method" (the indirect method's stages), "shared" (the raster passes
  // and direct light, which every configuration pays alike) and "total" (every stage):
  // stageMs by each stage's clock, wallMs by the steady one. "method" and "shared" only where
  // every frame says which stages are the method's (FrameTimes::methodStages).
  std::map<std::string, Summary> stageMs, wallMs;
  std::map<std::string, std::vector<double>> stageSamples, wallSamples;  // per repeat, in order
  // Per stage: kGlTimerQuery or kCpuWallClock (pipeline.h); a sum: its stages' when all agree,
  // else "mixed".
  std::map<std::string, std::string> clock;
  // The stages in the order the frames ran them (the maps above are sorted by name), then the
  // sums "method", "shared" and "total".
  std::vector<std::string> order;
  nlohmann::json toJson() const;
};

// The timings of `frames` (in order) summarised per stage, after `warmup` untimed frames.
TimingReport timingReport(const std::vector<FrameTimes>& frames, int warmup);
// Each stage's median time by its clock (ms), by stage name.
std::map<std::string, double> medianStageMs(const TimingReport& timing);
// Renders `warmup` untimed frames and `repeats` timed ones.
TimingReport measureFrames(Pipeline& pipeline, int warmup, int repeats);

}  // namespace lpvlab
