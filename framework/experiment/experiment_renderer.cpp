#include "framework/experiment/experiment_renderer.h"

#include <algorithm>
#include <utility>

#include "framework/raster/raster_choice.h"

namespace lpvlab {

RasterPlan chooseExperimentRaster(const Experiment& experiment) {
  const bool lightField =
      std::any_of(experiment.particles.begin(), experiment.particles.end(),
                  [](const ParticleGeometry& particles) { return particles.drawing().lightField; });
  const LightViews views =
      buildLightViews(experiment.scene.lights, experiment.scene.bounds(),
                      directionalFollow(experiment.settings, experiment.camera));
  const RasterRequest request{.glRenderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                              .lightFieldParticles = lightField,
                              .lightViews = int(views.views.size())};
  return chooseRaster(request, experiment.scene, experiment.settings);
}

ExperimentRenderer::ExperimentRenderer(Experiment& experiment, double seconds, ShaderCompiler& shaders)
    : pipeline_(experiment.scene, experiment.camera, experiment.settings,
                std::move(experiment.method), shaders, chooseExperimentRaster(experiment)),
      billboards_(experiment.particles, seconds, shaders, pipeline_) {}

}  // namespace lpvlab
