#include "framework/experiment/timing.h"

#include <algorithm>
#include <functional>
#include <set>

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

namespace {

// The clock of a sum of stages: theirs when all agree, else "mixed".
std::string clockOfSum(const std::map<std::string, std::string>& clock,
                       const std::function<bool(const std::string&)>& counted) {
  std::string sum;
  for (const auto& [stage, name] : clock)
    if (counted(stage)) sum = sum.empty() || sum == name ? name : "mixed";
  return sum;
}

}  // namespace

TimingReport timingReport(const std::vector<FrameTimes>& frames, int warmup) {
  std::map<std::string, std::vector<double>> byStage, wall;
  TimingReport report;
  // The method's and the shared stages' sums need every frame to say which stages are the
  // method's (frame records written before they did, 2026-11, do not).
  const bool split = !frames.empty() && std::all_of(frames.begin(), frames.end(), [](const FrameTimes& t) {
    return !t.methodStages.empty();
  });
  std::set<std::string> methodStages;
  for (const FrameTimes& times : frames) {
    std::map<std::string, double> stageSums, wallSums;  // total, method, shared
    for (const auto& [stage, ms] : times.stageMs) {
      byStage[stage].push_back(ms);
      stageSums[kTotalTime] += ms;
      stageSums[times.methodStages.count(stage) ? kMethodTime : kSharedTime] += ms;
    }
    for (const auto& [stage, ms] : times.wallMs) {
      wall[stage].push_back(ms);
      wallSums[kTotalTime] += ms;
      wallSums[times.methodStages.count(stage) ? kMethodTime : kSharedTime] += ms;
    }
    for (const char* sum : {kMethodTime, kSharedTime, kTotalTime}) {
      if (!split && sum != std::string(kTotalTime)) continue;
      byStage[sum].push_back(stageSums[sum]);
      wall[sum].push_back(wallSums[sum]);
    }
    for (const auto& [stage, clock] : times.clock) report.clock[stage] = clock;
    methodStages.insert(times.methodStages.begin(), times.methodStages.end());
    for (const std::string& stage : times.order)
      if (std::find(report.order.begin(), report.order.end(), stage) == report.order.end())
        report.order.push_back(stage);
  }
  // Each sum's clock: its stages' when all agree, else "mixed".
  std::map<std::string, std::string> sumClocks = {
      {kTotalTime, clockOfSum(report.clock, [](const std::string&) { return true; })}};
  if (split) {
    sumClocks[kMethodTime] = clockOfSum(report.clock, [&](const std::string& s) { return methodStages.count(s) > 0; });
    sumClocks[kSharedTime] = clockOfSum(report.clock, [&](const std::string& s) { return !methodStages.count(s); });
  }
  for (const char* sum : {kMethodTime, kSharedTime, kTotalTime}) {
    if (!byStage.count(sum)) continue;
    report.order.push_back(sum);
    if (!sumClocks[sum].empty()) report.clock[sum] = sumClocks[sum];
  }
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
