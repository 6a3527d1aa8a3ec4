#pragma once
// An experiment's pipeline with its particle systems' billboards: what `lpvlab run`, a sequence
// and `lpvlab bench` render with, wired in one place.

#include "framework/experiment/experiment.h"
#include "framework/gl/context.h"
#include "framework/gl/shader_compiler.h"
#include "framework/particles/particle_billboards.h"
#include "framework/pipeline/pipeline.h"

namespace lpvlab {

// Where the experiment's raster passes run ([compute] raster, [light_maps] shadows) on the current
// GL context: framework/raster/raster_choice.h, told the light views and whether a particle
// system is drawn as a light field.
RasterPlan chooseExperimentRaster(const Experiment& experiment);

// The GL context of an experiment's run ([gl] backend; framework/gl/context.h). "auto" falls back
// to "none" (no GL) when no GL context can be made and the run needs none: its strategies and
// raster passes may run on the CPU (compute.backend and compute.raster not "gl") and no particle
// system is drawn as a light field; `note` then says why. Otherwise the context's Error, with
// what gl.backend = "none" would need.
struct RunContext {
  std::unique_ptr<GlContext> context;
  std::string note;  // "" unless "auto" fell back to "none"
};
RunContext openRunContext(const Experiment& experiment);

class ExperimentRenderer {
public:
  // The pipeline of `experiment` (its strategies are moved into it) on the current GL context,
  // with the particles alive at `seconds` drawn by its raster passes. `shaders` must outlive it
  // (bench shares one compiler across its configurations).
  ExperimentRenderer(Experiment& experiment, double seconds, ShaderCompiler& shaders);

  Pipeline& pipeline() { return pipeline_; }
  ParticleBillboardSet& billboards() { return billboards_; }

private:
  Pipeline pipeline_;
  ParticleBillboardSet billboards_;
};

}  // namespace lpvlab
