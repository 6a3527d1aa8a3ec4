#include "framework/raster/raster_choice.h"

#include "framework/core/error.h"
#include "framework/gl/context.h"
#include "framework/pipeline/composition.h"
#include "framework/raster/raster_cost.h"
#include "framework/raster/ray_raster.h"

namespace lpvlab {

namespace {

bool softwareRenderer(const std::string& renderer) {
  return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

// The work of each raster pass of a frame, for the cost model.
std::map<std::string, RasterPassWork> passWork(const RasterRequest& request, const Scene& scene,
                                               const PipelineSettings& settings) {
  double drawn = 0.0, injecting = 0.0;
  for (const Mesh& mesh : scene.meshes) {
    if (!mesh.rasterised) continue;
    drawn += double(mesh.indices.size() / 3);
    if (scene.materials[std::size_t(mesh.material)].injects) injecting += double(mesh.indices.size() / 3);
  }
  const double views = request.lightViews;
  const double rsm = double(settings.rsmResolution) * settings.rsmResolution;
  const double shadow = double(settings.shadowResolution) * settings.shadowResolution;
  return {{kGBufferPass, {double(settings.width) * settings.height, 1.0, drawn, true}},
          {kRsmPass, {views * rsm, views, injecting, true}},
          {kShadowMapPass, {views * shadow, views, drawn, false}}};
}

// The passes "auto" gives the ray caster, each recorded with the model's estimates.
std::set<std::string> passesByModel(const RasterRequest& request, const Scene& scene,
                                    const PipelineSettings& settings, nlohmann::json& record) {
  std::set<std::string> passes;
  for (const auto& [pass, work] : passWork(request, scene, settings)) {
    const RasterPassCost cost = estimateRasterPass(work);
    if (cost.raysFaster()) passes.insert(pass);
    record["model_ms"][pass] = {{"llvmpipe", cost.llvmpipeMs}, {"embree", cost.raysMs}};
  }
  return passes;
}

}  // namespace

RasterPlan chooseRaster(const RasterRequest& request, const Scene& scene, const PipelineSettings& settings) {
  const std::string& raster = settings.raster;
  if (raster != "auto" && raster != "gl" && raster != "embree")
    throw Error("key 'compute.raster': '" + raster + "' is not one of auto, gl, embree");
  const bool cpuBackend = resolveBackend(settings.backend, request.glRenderer) != ComputeBackend::Gl;
  const bool rays = settings.shadow.rays;
  if (request.lightFieldParticles && (raster == "embree" || rays))
    throw Error(std::string(rays ? "key 'light_maps.shadows': \"rays\"" : "key 'compute.raster': \"embree\"") +
                " cannot see particle systems drawn as a light field (their billboards are GL "
                "programs); draw them as geometry (draw = \"geometry\") or use the GL rasteriser");
  if (rays && !cpuBackend)
    throw Error("key 'light_maps.shadows': \"rays\" are traced on the CPU, where direct light must "
                "then run: [compute] backend = \"cpu\", or \"auto\" on a software GL renderer");
  RasterPlan plan;
  plan.record = {{"requested", raster}};
  const bool noGl = request.glRenderer == kNoGlRenderer;  // gl.backend = "none"
  if (noGl && request.lightFieldParticles)
    throw Error("key 'gl.backend': \"none\" cannot draw particle systems drawn as a light field "
                "(their light fields and billboards are GL programs); draw them as geometry "
                "(draw = \"geometry\") or run with GL");
  if (noGl && raster == "gl")
    throw Error("key 'compute.raster': \"gl\" needs GL, and this run has none (gl.backend = \"none\"); "
                "use \"embree\" or \"auto\"");
  if (raster == "embree" || noGl) plan.hostPasses = {kGBufferPass, kRsmPass, kShadowMapPass};
  else if (raster == "auto" && softwareRenderer(request.glRenderer) && cpuBackend && !request.lightFieldParticles)
    plan.hostPasses = passesByModel(request, scene, settings, plan.record);
  if (!plan.hostPasses.empty() || rays) plan.host = std::make_unique<RayRaster>(scene);
  return plan;
}

}  // namespace lpvlab
