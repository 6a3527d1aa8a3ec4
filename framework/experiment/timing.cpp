#include "framework/experiment/timing.h"

#include <algorithm>

namespace lpvlab {

nlohmann::json TimingReport::toJson() const {
  nlohmann::json out = {{"warmup_frames", warmupFrames}, {"repeats", repeats}};
  for (const auto& [stage, summary] : stageMs) out["stage_ms"][stage] = summary.toJson();
  for (const auto& [stage, summary] : wallMs) out["wall_ms"][stage] = summary.toJson();
  out["clock"] = clock;
  out["stage_order"] = order;
  out["samples"] = {{"stage_ms", stageSamples}, {"wall_ms", wallSamples}};
  return out;
}

TimingReport timingReport(const std::vector<FrameTimes>& frames, int warmup) {
  std::map<std::string, std::vector<double>> byStage, wall;
  TimingReport report;
  for (const FrameTimes& times : frames) {
    double stageTotal = 0.0, wallTotal = 0.0;
    for (const auto& [stage, ms] : times.stageMs) byStage[stage].push_back(ms), stageTotal += ms;
    for (const auto& [stage, ms] : times.wallMs) wall[stage].push_back(ms), wallTotal += ms;
    byStage["total"].push_back(stageTotal);
    wall["total"].push_back(wallTotal);
    for (const auto& [stage, clock] : times.clock) report.clock[stage] = clock;
    for (const std::string& stage : times.order)
      if (std::find(report.order.begin(), report.order.end(), stage) == report.order.end())
        report.order.push_back(stage);
  }
  if (!frames.empty()) report.order.push_back("total");
  // The total adds the stages' times; it is one clock's only when every stage's is.
  std::string total;
  for (const auto& [stage, clock] : report.clock) total = total.empty() || total == clock ? clock : "mixed";
  if (!total.empty()) report.clock["total"] = total;
  report.warmupFrames = warmup;
  report.repeats = int(frames.size());
  for (auto& [stage, samples] : byStage) report.stageMs[stage] = summarize(samples);
  for (auto& [stage, samples] : wall) report.wallMs[stage] = summarize(samples);
  report.stageSamples = std::move(byStage);
  report.wallSamples = std::move(wall);
  return report;
}

std::map<std::string, double> medianStageMs(const TimingReport& timing) {
  std::map<std::string, double> medians;
  for (const auto& [stage, summary] : timing.stageMs) medians[stage] = summary.median;
  return medians;
}

TimingReport measureFrames(Pipeline& pipeline, int warmup, int repeats) {
  for (int i = 0; i < warmup; ++i) pipeline.renderFrame();
  std::vector<FrameTimes> frames;
  for (int i = 0; i < repeats; ++i) frames.push_back(pipeline.renderFrame());
  return timingReport(frames, warmup);
}

}  // namespace lpvlab
