#include "framework/experiment/experiment_renderer.h"

#include <utility>

namespace lpvlab {

ExperimentRenderer::ExperimentRenderer(Experiment& experiment, double seconds, ShaderCompiler& shaders)
    : pipeline_(experiment.scene, experiment.camera, experiment.settings,
                std::move(experiment.method), shaders),
      billboards_(experiment.particles, seconds, shaders, pipeline_) {}

}  // namespace lpvlab
