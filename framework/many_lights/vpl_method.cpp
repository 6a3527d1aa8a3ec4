#include "framework/many_lights/vpl_method.h"

#include "framework/many_lights/host_gbuffer.h"

namespace lpvlab {

std::string visibilityName(VplVisibility visibility) {
  switch (visibility) {
    case VplVisibility::None: return "none";
    case VplVisibility::Rays: return "rays";
    case VplVisibility::ShadowMaps: return "shadow_maps";
    case VplVisibility::Imperfect: return "imperfect_shadow_maps";
  }
  return "?";
}

VplVisibility readExactOrMappedVisibility(Params& p) {
  const std::string v = p.getChoice("visibility", "rays", {"rays", "shadow_maps", "none"});
  return v == "rays" ? VplVisibility::Rays : v == "none" ? VplVisibility::None : VplVisibility::ShadowMaps;
}

VplMethod::VplMethod(Params& p, VplVisibility visibility, const ImperfectSettings& imperfect)
    : visibility_(visibility), imperfect_(imperfect) {
  gather_.clamp = p.get<float>("clamp", 0.0f, {.min = 0.0f, .max = 1e30f});
  gather_.lobe.specularAlbedo = p.get<float>("specular_albedo", 0.0f, {.min = 0.0f, .max = 1.0f});
  gather_.lobe.exponent = p.get<float>("exponent", 32.0f, {.min = 0.0f, .max = 1e4f});
  gather_.lobe.sphereRadius = p.get<float>("sphere_radius", 0.0f, {.min = 0.0f, .max = 1e6f});
  compensate_ = p.get<bool>("clamp_compensation", false);
  if (compensate_ && !gather_.lobe.lambertianPoints())
    throw Error(p.where("clamp_compensation") + ": the compensation models Lambertian receivers "
                "and point VPLs; it cannot be combined with specular_albedo or sphere_radius");
  compensation_.samples = p.get<int>("compensation_samples", 4, {.min = 1, .max = 4096});
  if (compensate_ && !(gather_.clamp > 0.0f))
    throw Error(p.where("clamp_compensation") +
                ": there is nothing to compensate without a clamp (set clamp to a positive c)");
  compensation_.clamp = gather_.clamp;
  compensation_.minDistance = gather_.minDistance;
  gather_.visibility = visibility == VplVisibility::None   ? GatherVisibility::None
                       : visibility == VplVisibility::Rays ? GatherVisibility::Rays
                                                           : GatherVisibility::DepthMaps;
  if (gather_.visibility == GatherVisibility::DepthMaps) {
    mapSettings_.size = p.get<int>("shadow_map_size", 32, {.min = 2, .max = 1024});
    if ((mapSettings_.size & (mapSettings_.size - 1)) != 0)
      throw Error(p.where("shadow_map_size") + ": " + std::to_string(mapSettings_.size) +
                  " is not a power of two (pull-push halves the map down to one texel)");
    mapSettings_.normalOffsetTexels = p.get<float>("normal_offset", 1.5f, {.min = 0.0f, .max = 100.0f});
    mapSettings_.relativeBias = p.get<float>("depth_bias", 0.02f, {.min = 0.0f, .max = 10.0f});
  }
}

std::vector<std::string> VplMethod::stageNames() const {
  std::vector<std::string> stages = {"vpls"};
  if (gather_.visibility == GatherVisibility::DepthMaps) stages.push_back("vpl_shadow_maps");
  stages.push_back("indirect");
  if (compensate_) stages.push_back("clamp_compensation");
  return stages;
}

void VplMethod::prepare(const MethodSetup& setup) {
  scene_ = std::make_unique<RayScene>(setup.scene);
  if (visibility_ == VplVisibility::Imperfect)
    points_ = std::make_unique<SurfacePointSampler>(scene_->scene());
}

void VplMethod::moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) {
  if (geometryMoved)
    scene_->moveGeometry(scene);  // imperfect maps' points follow: drawn from the current vertices
  else if (lightsMoved)
    scene_->moveLights(scene);
}

void VplMethod::render(MethodFrame& frame) {
  frame.stage("vpls", [&] {
    scene_->update();
    makeVpls(*scene_, vpls_);
  });
  if (visibility_ == VplVisibility::ShadowMaps)
    frame.stage("vpl_shadow_maps",
                [&] { mapRays_ = renderDepthMapsByRays(scene_->embree(), vpls_, mapSettings_, maps_); });
  if (visibility_ == VplVisibility::Imperfect)
    frame.stage("vpl_shadow_maps", [&] {
      splatImperfectShadowMaps(scene_->scene(), *points_, vpls_, mapSettings_, imperfect_, maps_,
                               &imperfectCounts_);
    });
  frame.stage("indirect", [&] {
    const HostGBuffer g = hostGBuffer(frame.host, frame.gbuffer);
    gather_.lobe.eye = frame.camera.position;
    gatherVpls(g.position, g.normal, g.albedo, vpls_, gather_, {&scene_->embree(), &maps_},
               frame.indirect.host(), &gatherCounts_);
  });
  if (compensate_)
    frame.stage("clamp_compensation", [&] {
      const HostGBuffer g = hostGBuffer(frame.host, frame.gbuffer);
      compensation_.maxScatterings = vplBounces() + 1;
      compensateClamp(g.position, g.normal, g.albedo, *scene_, compensation_, frame.indirect.host(),
                      &compensationCounts_);
    });
}

std::map<std::string, std::vector<WorkCount>> VplMethod::work() const {
  // A gathered pair: its G f_r (about 20 multiply-adds), the clamp and the sum, 36 bytes of VPL
  // read; a shadow-map lookup about 30 more. Ray traversal is Embree's, counted in rays.
  const bool maps = gather_.visibility == GatherVisibility::DepthMaps;
  std::map<std::string, std::vector<WorkCount>> out = {{"vpls", sourceWork()}};
  std::vector<WorkCount> gather = {
      {"pixel-VPL pair", gatherCounts_.pairs, maps ? 54.0 : 24.0, double(sizeof(Vpl))}};
  if (visibility_ == VplVisibility::Rays) gather.push_back({"shadow ray", gatherCounts_.shadowRays, 0.0, 0.0});
  out["indirect"] = gather;
  // A compensation path: its weight at the first hit (about 20 multiply-adds); the rays it traces
  // (first, continuation and next-event shadow rays) are Embree's.
  if (compensate_)
    out["clamp_compensation"] = {{"compensation path", compensationCounts_.paths, 20.0, 0.0},
                                 {"compensation ray", compensationCounts_.rays, 0.0, 0.0}};
  if (visibility_ == VplVisibility::ShadowMaps)
    out["vpl_shadow_maps"] = {{"shadow-map ray", double(mapRays_), 0.0, 4.0}};
  if (visibility_ == VplVisibility::Imperfect) {
    const double texels = double(vpls_.size()) * mapSettings_.size * mapSettings_.size;
    // A splat: the paraboloid projection (about 25 multiply-adds), a depth read and written;
    // pull-push reads and writes each texel about twice over its levels.
    out["vpl_shadow_maps"] = {{"point splat", double(imperfectCounts_.splats), 25.0, 16.0},
                              {"pull-push texel", texels, 4.0, 16.0}};
  }
  return out;
}

std::size_t VplMethod::memoryBytes() const {
  return (scene_ ? scene_->memoryBytes() : 0) + vpls_.capacity() * sizeof(Vpl) + maps_.memoryBytes();
}

nlohmann::json VplMethod::statistics() const {
  const double total = gatherCounts_.radiance + gatherCounts_.clampedAway;
  nlohmann::json out = sourceStatistics();
  out["visibility"] = visibilityName(visibility_);
  out["vpls"] = vpls_.size();
  out["gathered_pairs"] = gatherCounts_.pairs;
  out["receivers"] = {{"specular_albedo", gather_.lobe.specularAlbedo},
                     {"exponent", gather_.lobe.exponent},
                     {"sphere_radius_m", gather_.lobe.sphereRadius},
                     {"lights", gather_.lobe.sphereRadius > 0.0f ? "virtual spherical lights" : "points"}};
  out["clamp"] = {{"c", gather_.clamp},
                  {"largest_g_fr", gatherCounts_.largestGfr},
                  {"removed_radiance_sum", gatherCounts_.clampedAway},
                  {"kept_radiance_sum", gatherCounts_.radiance},
                  {"removed_fraction", total > 0.0 ? gatherCounts_.clampedAway / total : 0.0},
                  {"units", "W/(m^2 sr) summed over the pixels and RGB channels of indirect"}};
  if (compensate_) {
    const ClampCompensationCounts& k = compensationCounts_;
    out["clamp"]["compensation"] = {
        {"samples_per_pixel", compensation_.samples},
        {"added_radiance_sum", k.radiance},
        {"added_over_removed", gatherCounts_.clampedAway > 0.0 ? k.radiance / gatherCounts_.clampedAway : 0.0},
        {"paths", k.paths},
        {"weighted_path_fraction", k.paths > 0.0 ? k.weightedPaths / k.paths : 0.0},
        {"compensated_pixel_fraction", k.pixels > 0.0 ? k.compensatedPixels / k.pixels : 0.0},
        {"rays", k.rays},
        {"max_scatterings", compensation_.maxScatterings}};
  }
  if (visibility_ == VplVisibility::Rays) out["shadow_rays"] = gatherCounts_.shadowRays;
  if (visibility_ == VplVisibility::ShadowMaps) out["shadow_map_rays"] = mapRays_;
  if (visibility_ == VplVisibility::Imperfect) {
    const double disk = double(std::max<std::size_t>(imperfectCounts_.diskTexels, 1));
    out["imperfect_shadow_maps"] = {
        {"points_per_vpl", imperfect_.pointsPerVpl},
        {"splats", imperfectCounts_.splats},
        {"hole_fraction_before_pull_push", double(imperfectCounts_.holesBefore) / disk},
        {"hole_fraction_after_pull_push", double(imperfectCounts_.holesAfter) / disk}};
  }
  return out;
}

LightPathMethod::LightPathMethod(Params& p, VplVisibility visibility, const ImperfectSettings& imperfect)
    : VplMethod(p, visibility, imperfect) {
  paths_.paths = p.get<int>("light_paths", 256, {.min = 1, .max = 1 << 24});
  paths_.firstHitsOnly = p.get<bool>("one_bounce", false);
  paths_.rouletteAfter = p.get<int>("roulette_after", 1, {.min = 0, .max = 100000});
  paths_.maxBounces = p.get<int>("max_bounces", 64, {.min = 1, .max = 100000});
  paths_.seed = std::uint64_t(p.get<int>("seed", 1, {.min = 0}));
  paths_.sampler = samplerFromName(p.getChoice("sampler", "independent", samplerNames()));
  setSeed(paths_.seed);
}

void LightPathMethod::makeVpls(const RayScene& scene, std::vector<Vpl>& vpls) {
  vpls = traceLightPaths(scene, paths_, &counts_);
}

std::vector<WorkCount> LightPathMethod::sourceWork() const {
  return {{"light-path ray", double(counts_.rays), 0.0, 0.0}};
}

nlohmann::json LightPathMethod::sourceStatistics() const {
  return {{"light_paths", paths_.paths},
          {"sampler", samplerName(paths_.sampler)},
          {"light_path_rays", counts_.rays},
          {"emitted_flux_W", {counts_.emittedFlux.r, counts_.emittedFlux.g, counts_.emittedFlux.b}}};
}

}  // namespace lpvlab
