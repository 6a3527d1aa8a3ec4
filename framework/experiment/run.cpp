#include "framework/experiment/run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "framework/core/error.h"
#include "framework/experiment/experiment_renderer.h"
#include "framework/experiment/run_outputs.h"
#include "framework/experiment/sequence.h"
#include "framework/core/atomic_file.h"
#include "framework/io/npy.h"
#include "framework/metrics/metrics.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {

nlohmann::json writeGridDump(const GridDump& dump, const std::string& outDir,
                             const std::string& stem) {
  const std::filesystem::path dir(outDir);
  const std::string npy = stem + ".npy", json = stem + ".json";
  writeNpy((dir / npy).string(), {dump.shape, dump.values});
  nlohmann::json described = dump.description;
  described["file"] = npy;
  described["shape"] = dump.shape;
  described["axes"] = dump.axes;
  described["dtype"] = "float32, little-endian, C order";
  writeTextAtomically((dir / json).string(), described.dump(2) + "\n");
  return {{"npy", npy}, {"json", json}, {"shape", dump.shape}, {"axes", dump.axes}};
}

nlohmann::json runExperiment(Experiment& experiment, const GlContext& context,
                             const std::string& outDir) {
  if (experiment.animation.animated()) return runSequence(experiment, context, outDir);
  std::optional<Reference> reference;
  if (experiment.compareWithReference)
    reference = ensureReference(experiment.scene, experiment.camera, experiment.reference);
  ShaderCompiler shaders;
  ExperimentRenderer renderer(experiment, experiment.animation.frameTime(0), shaders);
  Pipeline& pipeline = renderer.pipeline();
  const TimingReport timing = measureFrames(pipeline, experiment.warmupFrames, experiment.repeats);
  std::vector<NamedImage> aovs = pipeline.readOutputs();
  requireFiniteImages(aovs);
  // The method's diagnostics after the timed frames (LPV's injection flux balance), with what
  // they found suspect.
  nlohmann::json audit = pipeline.method().audit();
  const std::vector<std::string> auditWarnings =
      audit.value("warnings", std::vector<std::string>{});
  audit.erase("warnings");

  const std::string hash = sceneHash(experiment.scene);
  nlohmann::json manifest = describeRun(experiment, context, pipeline, hash, medianStageMs(timing));
  manifest["timing"] = timing.toJson();
  manifest.update(audit);
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

  std::vector<std::string> warnings = resultWarnings(aovs, manifest);
  warnings.insert(warnings.end(), auditWarnings.begin(), auditWarnings.end());
  if (!warnings.empty()) manifest["warnings"] = warnings;

  std::filesystem::create_directories(outDir);
  const std::filesystem::path dir(outDir);
  if (experiment.dumpGrid) manifest["outputs"]["grid"] = writeGridDump(pipeline.method().dumpGrid(), outDir);
  writeExr((dir / "images.exr").string(), aovs,
           {{"lpvlab:experiment", experiment.name}, {"lpvlab:scene_hash", hash}});
  const float exposure = experiment.exposureStops +
                         (experiment.autoExposure ? middleGreyExposure(aovs[2].image) : 0.0f);
  manifest["outputs"]["png_exposure_stops"] = exposure;
  writePng((dir / "combined.png").string(), aovs[2].image, exposure, experiment.toneCurve,
           experiment.whiteStops);
  if (heatMap) writePng((dir / heatMapName).string(), *heatMap, 0.0f, ToneCurve::Clamp);
  writeTextAtomically((dir / "manifest.json").string(), manifest.dump(2) + "\n");
  return manifest;
}

}  // namespace lpvlab
