#pragma once
// [compute] raster: where a run's raster passes (G-buffer, shadow maps, RSMs) run.
//   "gl"      GL's rasteriser (a GPU's, or llvmpipe's on the CPU)
//   "embree"  every pass by ray casting on the CPU (ray_raster.h)
//   "auto"    on a software GL renderer (llvmpipe, softpipe) with the compute backend on the CPU,
//             each pass where raster_cost.h's model of both says it is faster (ray casting wins
//             on scenes of many triangles); without GL (gl.backend = "none") every pass; else
//             "gl" (refused without GL)
// The images are the same up to edge sampling, so the choice changes times, not results; the
// manifest's compute report records it per pass with the model's estimates.
// [light_maps] shadows = "rays" (exact shadow rays for direct light, no shadow maps) makes the
// ray caster whatever the passes use, and needs direct light on the CPU.
// Particle systems drawn as a light field are GL programs (billboards): "embree" and shadow rays
// refuse them, and "auto" then takes "gl".

#include <string>

#include "framework/pipeline/host_raster.h"
#include "framework/pipeline/pipeline.h"

namespace lpvlab {

struct RasterRequest {
  std::string glRenderer;             // GL_RENDERER of the run's context
  bool lightFieldParticles = false;   // some particle system is drawn as a light field
  int lightViews = 0;                 // views of the light maps (a point light's six faces, ...)
};

// The plan for settings.raster and settings.shadow.rays on `scene`; "auto" looks at the renderer
// and at settings.backend resolved against it. Throws an Error naming the key for an unknown
// choice, "embree" or shadow rays with light-field particles, or shadow rays with direct light
// on GL.
RasterPlan chooseRaster(const RasterRequest& request, const Scene& scene, const PipelineSettings& settings);

}  // namespace lpvlab
