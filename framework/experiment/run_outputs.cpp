#include "framework/experiment/run_outputs.h"

#include <assimp/version.h>
#include <glslang/build_info.h>

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "framework/experiment/json_path.h"
#include "framework/io/provenance.h"
#include "framework/metrics/metrics.h"
#include "framework/reference/statistical_compare.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {

void requireFiniteImages(const std::vector<NamedImage>& aovs) {
  for (const NamedImage& aov : aovs) {
    std::size_t bad = 0;
    for (float v : aov.image.pixels) bad += !std::isfinite(v);
    if (bad)
      throw Error("output '" + aov.name + "': " + std::to_string(bad) +
                  " values are NaN or Inf; nothing was written");
  }
}

std::vector<std::string> resultWarnings(const std::vector<NamedImage>& aovs,
                                        const nlohmann::json& manifest) {
  const auto zero = [&](const char* name) {
    for (const NamedImage& aov : aovs)
      if (aov.name == name)
        return std::all_of(aov.image.pixels.begin(), aov.image.pixels.end(),
                           [](float v) { return v == 0.0f; });
    return false;  // not an output of this run
  };
  std::vector<std::string> warnings;
  if (zero("direct") && zero("indirect"))
    warnings.push_back("every value of 'direct' and 'indirect' is zero: nothing the camera sees is "
                       "lit (lights black or of zero intensity, outside the view, or no surface "
                       "they reach)");
  else if (zero("indirect"))
    warnings.push_back("'indirect' is zero everywhere while 'direct' is not");
  // A solve that stopped before its tolerance (radiosity's max_iterations, say).
  if (const auto* statistics = findPath(manifest, "indirect_method.statistics")) {
    const nlohmann::json flat = statistics->flatten();  // items() refers into it
    for (const auto& [path, value] : flat.items())
      if (path.ends_with("/converged") && value.is_boolean() && !value.get<bool>())
        warnings.push_back("the indirect method's " + path.substr(1, path.size() - 11) +
                           " did not converge (statistics" + path + " = false)");
  }
  return warnings;
}

namespace {

nlohmann::json versions(const GlContext& context) {
  nlohmann::json v = libraryVersions();
  v["assimp"] = std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) +
                "." + std::to_string(aiGetVersionPatch());
  v["glslang"] = std::to_string(GLSLANG_VERSION_MAJOR) + "." +
                 std::to_string(GLSLANG_VERSION_MINOR) + "." +
                 std::to_string(GLSLANG_VERSION_PATCH);
  v["gl_backend"] = context.backend();
  v["gl_renderer"] = context.renderer();
  v["gl_version"] = context.version();
  return v;
}

}  // namespace

Image coverageMask(const Image& depth) {
  Image mask(depth.width, depth.height, 1);
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = depth.pixels[i] > 0.0f;
  return mask;
}

namespace {

// The reference's own noise as an RMSE: the root of the mean variance of its pixel means over the
// covered pixels and channels. An RMSE against it cannot fall much below this however exact the
// run is (the report draws it as the noise floor of convergence curves).
double noiseFloorRmse(const Image& varianceOfMean, const Image& mask) {
  double sum = 0.0, count = 0.0;
  const int channels = varianceOfMean.channels;
  for (int y = 0; y < varianceOfMean.height; ++y)
    for (int x = 0; x < varianceOfMean.width; ++x) {
      if (mask.at(x, y, 0) <= 0.0f) continue;
      for (int c = 0; c < channels; ++c) sum += std::max(0.0, double(varianceOfMean.at(x, y, c)));
      count += channels;
    }
  return count > 0.0 ? std::sqrt(sum / count) : 0.0;
}

// The standard error of imageMean of the reference, from its variance-of-mean image. Its pixels are
// independent estimates; a pixel's channels come from the same paths, so they are taken as fully
// correlated, which bounds the error from above: sqrt(sum_p (sum_c sqrt(v_pc))^2) / (P C).
double meanStandardError(const Image& varianceOfMean) {
  const std::size_t values = varianceOfMean.pixels.size();
  if (values == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t p = 0; p < values; p += std::size_t(varianceOfMean.channels)) {
    double deviation = 0.0;
    for (int c = 0; c < varianceOfMean.channels; ++c)
      deviation += std::sqrt(std::max(0.0, double(varianceOfMean.pixels[p + std::size_t(c)])));
    sum += deviation * deviation;
  }
  return std::sqrt(sum) / double(values);
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

}  // namespace

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
    const Image& variance = findAov(ref.aovs, theirs + "_variance");
    const ComparisonResult z = compareToExact(b, variance, a);
    const double meanRun = imageMean(a), meanReference = imageMean(b);
    nlohmann::json& pair = out["comparison"][mine + "_vs_" + theirs];
    pair = {{"mean_run", meanRun},
            {"mean_reference", meanReference},
            {"z_tests", z.tests},
            {"z_rejected", z.rejected},
            {"z_threshold", z.threshold},
            {"mean_z", z.meanZ},
            {"metrics", computeMetrics(a, b, &mask).toJson()}};
    // Beside the metrics (so the summary has them per pair), but not errors of the run: the
    // reference's noise, the ratio of the means and the reference mean's relative standard error
    // (what a test of the run's mean over seeds needs: analysis/lpvlab_analysis/seeds.py).
    pair["metrics"]["noise_floor_rmse"] = noiseFloorRmse(variance, mask);
    pair["metrics"]["ratio_of_means"] = meanReference > 0.0 ? meanRun / meanReference : 0.0;
    pair["metrics"]["mean_reference_relative_standard_error"] =
        meanReference > 0.0 ? meanStandardError(variance) / meanReference : 0.0;
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

namespace {

// Each particle system's size: its model, the most copies alive at once (the triangles it adds to
// the scene) and how many are alive at frame 0 (a sequence's frame records give every frame's).
nlohmann::json particlesJson(const Experiment& experiment) {
  nlohmann::json systems = nlohmann::json::array();
  for (const ParticleGeometry& particles : experiment.particles) {
    const std::size_t capacity = particles.system().capacity();
    systems.push_back(
        {{"name", particles.system().name},
         {"model", particles.model().source},
         {"model_triangles", particles.model().triangleCount()},
         {"capacity", capacity},
         {"triangles", capacity * particles.model().triangleCount()},
         {"alive_at_frame_0",
          particlesAt(particles.system(), experiment.animation.frameTime(0)).size()}});
  }
  return systems;
}

// The configuration keys a sweep's summary gives a column each (sweep_summary.h) beside its swept
// keys: the method and the scene, the method's own (IndirectMethod::summaryKeys), and the first
// particle system's drawing, by which the report tells geometry from light fields.
nlohmann::json summaryKeys(const Experiment& experiment, const IndirectMethod& method) {
  nlohmann::json keys = {"indirect.method"};
  for (const std::string& key : method.summaryKeys()) keys.push_back(key);
  keys.push_back("scene.file");
  if (!experiment.particles.empty()) keys.push_back("particles[0].draw");
  return keys;
}

}  // namespace

nlohmann::json describeRun(const Experiment& experiment, const GlContext& context,
                           const Pipeline& pipeline, const std::string& sceneHash,
                           const std::map<std::string, double>& medianStageMs) {
  nlohmann::json description = {{"lpvlab_version", LPVLAB_VERSION},
          {"experiment", experiment.name},
          {"experiment_file", experiment.file.empty() ? "(built-in default)" : experiment.file},
          {"created_utc", utcTimestamp()},
          {"git_revision", lpvlabRevision()},
          {"configuration", experiment.configuration},
          {"scene",
           {{"source", experiment.scene.source},
            {"hash", sceneHash},
            {"triangles", experiment.scene.triangleCount()},
            {"lights", experiment.scene.lights.size()}}},
          {"libraries", versions(context)},
          {"host", hostInfo()},
          {"compute", pipeline.computeReport()},
          {"timing_method",
           {{"stage",
             "timing.stage_ms: each stage by its clock, timing.clock: gl_timer_query = GL "
             "timestamp queries around the stage's GL work, on libraries.gl_renderer; "
             "cpu_wall_clock = the steady clock around a stage whose strategies run on the CPU "
             "backend (see compute), on host.cpu, its transfers to and from GL included"},
            {"wall", "timing.wall_ms: steady clock around each stage, ended by glFinish"}}},
          {"memory_bytes", pipeline.memoryReport()},
          {"work", pipeline.workReport()},
          {"gpu_work", pipeline.workReport(true)}};
  if (!experiment.particles.empty()) description["particles"] = particlesJson(experiment);
  description["summary_keys"] = summaryKeys(experiment, pipeline.method());
  description.update(pipeline.method().describe(medianStageMs));
  return description;
}

}  // namespace lpvlab
