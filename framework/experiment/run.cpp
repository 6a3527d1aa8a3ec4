#include "framework/experiment/run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "framework/core/error.h"
#include "framework/experiment/run_outputs.h"
#include "framework/experiment/sequence.h"
#include "framework/io/atomic_file.h"
#include "framework/metrics/metrics.h"
#include "framework/particles/particle_billboards.h"
#include "framework/scene/scene_loader.h"

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

double medianStageMs(const TimingReport& timing, const std::string& stage) {
  const auto found = timing.stageMs.find(stage);
  return found == timing.stageMs.end() ? 0.0 : found->second.median;
}

TimingReport measureFrames(Pipeline& pipeline, int warmup, int repeats) {
  for (int i = 0; i < warmup; ++i) pipeline.renderFrame();
  std::vector<FrameTimes> frames;
  for (int i = 0; i < repeats; ++i) frames.push_back(pipeline.renderFrame());
  return timingReport(frames, warmup);
}

nlohmann::json runExperiment(Experiment& experiment, const GlContext& context,
                             const std::string& outDir) {
  if (experiment.animation.animated()) return runSequence(experiment, context, outDir);
  std::optional<Reference> reference;
  if (experiment.compareWithReference)
    reference = ensureReference(experiment.scene, experiment.camera, experiment.reference);
  ShaderCompiler shaders;
  Pipeline pipeline(experiment.scene, experiment.camera, experiment.settings,
                    std::move(experiment.strategies), shaders);
  const ParticleBillboardSet billboards(experiment.particles, experiment.animation.frameTime(0),
                                        shaders, pipeline);
  const TimingReport timing = measureFrames(pipeline, experiment.warmupFrames, experiment.repeats);
  std::vector<NamedImage> aovs = pipeline.readOutputs();
  requireFiniteImages(aovs);
  // LPV's injection bookkeeping (another method injects into no grid).
  std::optional<InjectionBalance> balance;
  if (!pipeline.strategies().method) balance = pipeline.measureInjection();

  const std::string hash = sceneHash(experiment.scene);
  nlohmann::json manifest =
      describeRun(experiment, context, pipeline, hash, medianStageMs(timing, "propagation"));
  manifest["timing"] = timing.toJson();
  if (balance) manifest["injection_flux_W"] = injectionFluxJson(*balance);
  manifest["outputs"] = {
      {"exr", "images.exr"},
      {"png", "combined.png"},
      {"aovs", {"direct", "indirect", "combined", "albedo", "normal", "depth"}},
      {"units", "radiance W/(m^2 sr); depth: view depth in metres, 0 = no surface"}};

  std::optional<Image> heatMap;
  std::string heatMapName;
  if (reference) {
    const Image mask = coverageMask(findAov(aovs, "depth"));
    manifest["reference"] = compareWithReference(aovs, *reference, mask, experiment.comparison);
    const auto& [mine, theirs] = experiment.comparison.pairs.front();
    heatMap = errorHeatMap(findAov(aovs, mine), findAov(reference->aovs, theirs), &mask);
    heatMapName = "error_" + mine + ".png";
    manifest["outputs"]["error_map"] =
        heatMapName + " (FLIP of " + mine + " against the reference's " + theirs + ")";
  }

  if (const std::vector<std::string> warnings = resultWarnings(aovs, manifest); !warnings.empty())
    manifest["warnings"] = warnings;

  std::filesystem::create_directories(outDir);
  const std::filesystem::path dir(outDir);
  writeExr((dir / "images.exr").string(), aovs,
           {{"lpvlab:experiment", experiment.name}, {"lpvlab:scene_hash", hash}});
  const float exposure = experiment.exposureStops +
                         (experiment.autoExposure ? middleGreyExposure(aovs[2].image) : 0.0f);
  manifest["outputs"]["png_exposure_stops"] = exposure;
  writePng((dir / "combined.png").string(), aovs[2].image, exposure);
  if (heatMap) writePng((dir / heatMapName).string(), *heatMap, 0.0f, false);
  writeTextAtomically((dir / "manifest.json").string(), manifest.dump(2) + "\n");
  return manifest;
}

}  // namespace lpvlab
