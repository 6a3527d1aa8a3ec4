#include "framework/experiment/run.h"

#include <assimp/version.h>
#include <glslang/build_info.h>

#include <cmath>
#include <optional>
#include <filesystem>

#include "framework/core/error.h"
#include "framework/io/atomic_file.h"
#include "framework/io/provenance.h"
#include "framework/metrics/metrics.h"
#include "framework/reference/statistical_compare.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {

namespace {

void requireFiniteImages(const std::vector<NamedImage>& aovs) {
  for (const NamedImage& aov : aovs) {
    std::size_t bad = 0;
    for (float v : aov.image.pixels) bad += !std::isfinite(v);
    if (bad)
      throw Error("output '" + aov.name + "': " + std::to_string(bad) +
                  " values are NaN or Inf; nothing was written");
  }
}

nlohmann::json versions(const GlContext& context) {
  nlohmann::json v = libraryVersions();
  v["assimp"] = std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) +
                "." + std::to_string(aiGetVersionPatch());
  v["glslang"] = std::to_string(GLSLANG_VERSION_MAJOR) + "." +
                 std::to_string(GLSLANG_VERSION_MINOR) + "." + std::to_string(GLSLANG_VERSION_PATCH);
  v["gl_backend"] = context.backend();
  v["gl_renderer"] = context.renderer();
  v["gl_version"] = context.version();
  return v;
}

double mean(const Image& image) {
  double sum = 0.0;
  for (float v : image.pixels) sum += v;
  return image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
}

// The pixels where the camera sees a surface (depth 0 marks the background).
Image coverageMask(const Image& depth) {
  Image mask(depth.width, depth.height, 1);
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = depth.pixels[i] > 0.0f;
  return mask;
}

// `mask` restricted to a region of the image (ComparisonSettings::Region).
Image regionMask(const Image& mask, const glm::vec4& rect) {
  Image out = mask;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      const float u = (x + 0.5f) / float(mask.width), v = (y + 0.5f) / float(mask.height);
      if (u < rect.x || u >= rect.z || v < rect.y || v >= rect.w) out.at(x, y, 0) = 0.0f;
    }
  return out;
}

// How the run's outputs compare with the reference's, per configured pair (run output, reference
// output), over the pixels the camera sees: the metrics (framework/metrics/metrics.h), per region
// too, the means and their ratio, and a per-pixel z-test against the reference's variance at a
// Sidak-corrected 1% family level (how many pixel channels the reference's noise can't explain).
nlohmann::json compareWithReference(const std::vector<NamedImage>& run, const Reference& ref,
                                    const Image& mask, const ComparisonSettings& settings) {
  nlohmann::json out = {{"key", ref.key},
                        {"directory", ref.directory},
                        {"samples", ref.samples},
                        {"relative_error", ref.relativeError},
                        {"reused", ref.reused}};
  for (const auto& [mine, theirs] : settings.pairs) {
    const Image& a = findAov(run, mine);
    const Image& b = findAov(ref.aovs, theirs);
    const ComparisonResult z = compareToExact(b, findAov(ref.aovs, theirs + "_variance"), a);
    const double meanRun = mean(a), meanReference = mean(b);
    nlohmann::json& pair = out["comparison"][mine + "_vs_" + theirs];
    pair = {{"mean_run", meanRun}, {"mean_reference", meanReference},
            {"ratio_of_means", meanReference > 0.0 ? meanRun / meanReference : 0.0},
            {"z_tests", z.tests}, {"z_rejected", z.rejected}, {"z_threshold", z.threshold},
            {"mean_z", z.meanZ}, {"metrics", computeMetrics(a, b, &mask).toJson()}};
    for (const ComparisonSettings::Region& region : settings.regions) {
      const Image inside = regionMask(mask, region.rect);
      double covered = 0.0;
      for (float m : inside.pixels) covered += m;
      // A region that sees only background has no figures (rather than failing the run).
      pair["regions"][region.name] =
          covered > 0.0 ? computeMetrics(a, b, &inside).toJson() : nlohmann::json(nullptr);
    }
  }
  return out;
}

// The flux bookkeeping of injection (W, RGB summed): what the RSMs reflect, what the grid holds,
// and what each injection added. For an RSM injection, RSM flux minus what it added fell outside
// the grid; other injections (sky light) add flux that is not in the RSMs.
nlohmann::json injectionFluxJson(const InjectionBalance& balance) {
  nlohmann::json added = nlohmann::json::object();
  for (const auto& [table, flux] : balance.byInjection) added[table] = flux;
  return {{"rsm", balance.rsmFlux}, {"grid", balance.gridFlux}, {"added_by", added}};
}

// Where each light grid sat (finest first; one entry without cascades).
nlohmann::json cascadeLevelsJson(const Pipeline& pipeline) {
  nlohmann::json levels = nlohmann::json::array();
  for (const LightGrid& grid : pipeline.levels()) {
    const GridGeometry& g = grid.geometry;
    levels.push_back({{"origin", {g.origin.x, g.origin.y, g.origin.z}},
                      {"cell_size", g.cellSize},
                      {"cells", {g.resolution.x, g.resolution.y, g.resolution.z}}});
  }
  return levels;
}

}  // namespace

nlohmann::json TimingReport::toJson() const {
  nlohmann::json out = {{"warmup_frames", warmupFrames}, {"repeats", repeats}};
  for (const auto& [stage, summary] : gpuMs) out["gpu_ms"][stage] = summary.toJson();
  for (const auto& [stage, summary] : wallMs) out["wall_ms"][stage] = summary.toJson();
  out["samples"] = {{"gpu_ms", gpuSamples}, {"wall_ms", wallSamples}};
  return out;
}

TimingReport measureFrames(Pipeline& pipeline, int warmup, int repeats) {
  for (int i = 0; i < warmup; ++i) pipeline.renderFrame();
  std::map<std::string, std::vector<double>> gpu, wall;
  for (int i = 0; i < repeats; ++i) {
    const FrameTimes times = pipeline.renderFrame();
    double gpuTotal = 0.0, wallTotal = 0.0;
    for (const auto& [stage, ms] : times.gpuMs) gpu[stage].push_back(ms), gpuTotal += ms;
    for (const auto& [stage, ms] : times.wallMs) wall[stage].push_back(ms), wallTotal += ms;
    gpu["total"].push_back(gpuTotal);
    wall["total"].push_back(wallTotal);
  }
  TimingReport report;
  report.warmupFrames = warmup;
  report.repeats = repeats;
  for (auto& [stage, samples] : gpu) report.gpuMs[stage] = summarize(samples);
  for (auto& [stage, samples] : wall) report.wallMs[stage] = summarize(samples);
  report.gpuSamples = std::move(gpu);
  report.wallSamples = std::move(wall);
  return report;
}

nlohmann::json runExperiment(Experiment& experiment, const GlContext& context,
                             const std::string& outDir) {
  std::optional<Reference> reference;
  if (experiment.compareWithReference)
    reference = ensureReference(experiment.scene, experiment.camera, experiment.reference);
  ShaderCompiler shaders;
  Pipeline pipeline(experiment.scene, experiment.camera, experiment.settings,
                    std::move(experiment.strategies), shaders);
  const TimingReport timing = measureFrames(pipeline, experiment.warmupFrames, experiment.repeats);
  std::vector<NamedImage> aovs = pipeline.readOutputs();
  requireFiniteImages(aovs);
  const InjectionBalance balance = pipeline.measureInjection();

  const std::string hash = sceneHash(experiment.scene);
  const double propagationMs = timing.gpuMs.at("propagation").median;
  const int iterations = pipeline.strategies().propagation->iterations();
  nlohmann::json manifest = {
      {"lpvlab_version", LPVLAB_VERSION},
      {"experiment", experiment.name},
      {"experiment_file", experiment.file.empty() ? "(built-in default)" : experiment.file},
      {"created_utc", utcTimestamp()},
      {"git_revision", gitRevision(LPVLAB_SOURCE_DIR)},
      {"configuration", experiment.configuration},
      {"scene",
       {{"source", experiment.scene.source},
        {"hash", hash},
        {"triangles", experiment.scene.triangleCount()},
        {"lights", experiment.scene.lights.size()}}},
      {"libraries", versions(context)},
      {"host", hostInfo()},
      {"timing", timing.toJson()},
      {"compute", pipeline.computeReport()},
      {"timing_method",
       {{"gpu",
         "GL timestamp queries around each stage; for a stage on the CPU "
         "backend (see compute) its wall time"},
        {"wall", "steady clock, each stage ended by glFinish"}}},
      {"propagation_cell_iterations_per_second",
       propagationMs > 0.0
           ? double(pipeline.propagatedCells()) * iterations / (propagationMs * 1e-3)
           : 0.0},
      {"cascade_levels", cascadeLevelsJson(pipeline)},
      {"memory_bytes", pipeline.memoryReport()},
      {"work", pipeline.workReport()},
      {"gpu_work", pipeline.workReport(true)},
      {"injection_flux_W", injectionFluxJson(balance)},
      {"outputs",
       {{"exr", "images.exr"},
        {"png", "combined.png"},
        {"aovs", {"direct", "indirect", "combined", "albedo", "normal", "depth"}},
        {"units", "radiance W/(m^2 sr); depth: view depth in metres, 0 = no surface"}}}};

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
