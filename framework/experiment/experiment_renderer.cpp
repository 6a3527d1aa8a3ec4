#include "framework/experiment/experiment_renderer.h"

#include <algorithm>
#include <utility>

#include "framework/core/error.h"
#include "framework/gl/context.h"
#include "framework/raster/raster_choice.h"

namespace lpvlab {

namespace {

// Whether some particle system is drawn as a light field (its billboards are GL programs).
bool drawsLightField(const Experiment& experiment) {
  return std::any_of(experiment.particles.begin(), experiment.particles.end(),
                     [](const ParticleGeometry& particles) { return particles.drawing().lightField; });
}

}  // namespace

RasterPlan chooseExperimentRaster(const Experiment& experiment) {
  const bool lightField = drawsLightField(experiment);
  const LightViews views =
      buildLightViews(experiment.scene.lights, experiment.scene.bounds(),
                      directionalFollow(experiment.settings, experiment.camera));
  const RasterRequest request{.glRenderer = GlContext::currentRenderer(),
                              .lightFieldParticles = lightField,
                              .lightViews = int(views.views.size())};
  return chooseRaster(request, experiment.scene, experiment.settings);
}

RunContext openRunContext(const Experiment& experiment) {
  if (experiment.glBackend != "auto") return {GlContext::create(experiment.glBackend), ""};
  try {
    return {GlContext::create("auto"), ""};
  } catch (const Error& error) {
    const bool lightField = drawsLightField(experiment);
    const std::string& backend = experiment.settings.backend;
    const std::string& raster = experiment.settings.raster;
    if (backend == "gl" || raster == "gl" || lightField)
      throw Error(std::string(error.what()) + "; without GL (gl.backend = \"none\") this run cannot "
                  "run: it asks for GL (" + (lightField ? "a light-field particle system" :
                  backend == "gl" ? "compute.backend = \"gl\"" : "compute.raster = \"gl\"") + ")");
    return {GlContext::create("none"), "no GL context could be made (" + std::string(error.what()) +
                                           "): every stage runs on the CPU (gl.backend = \"none\")"};
  }
}

ExperimentRenderer::ExperimentRenderer(Experiment& experiment, double seconds, ShaderCompiler& shaders)
    : pipeline_(experiment.scene, experiment.camera, experiment.settings,
                std::move(experiment.method), shaders, chooseExperimentRaster(experiment)),
      billboards_(experiment.particles, seconds, shaders, pipeline_) {}

}  // namespace lpvlab
