#pragma once
// What the VPL methods of variants/methods/ share: each frame, VPLs from a source (light paths
// for instant radiosity and imperfect shadow maps, the kept set of incremental instant
// radiosity), their visibility, and the gather with the clamp (vpl_gather.h). Visibility:
//   none                  V = 1
//   rays                  exact: an Embree shadow ray per (pixel, VPL) pair
//   shadow_maps           a paraboloid shadow map per VPL, each texel's depth by an Embree ray
//                         through its centre (seed 001, 2.4; vpl_depth_maps.h)
//   imperfect             imperfect shadow maps: points splatted, holes filled by pull-push (3.3)
// Stages: "vpls" (the source; Embree's rebuild after the geometry moved), "vpl_shadow_maps" (with
// shadow maps of either kind), "indirect" (the gather), "clamp_compensation" (with it).
//
// Keys read here (docs/methods.md): clamp, clamp_compensation (the clamped-away light added back
// by a short path-traced gather: clamp_compensation.h) and compensation_samples; specular_albedo
// and exponent (a glossy lobe on every receiver) and sphere_radius (virtual spherical lights:
// vpl_transfer.h); with shadow maps of either kind shadow_map_size, normal_offset, depth_bias.
// LightPathMethod adds light_paths, one_bounce, roulette_after, max_bounces, seed.

#include <memory>
#include <string>
#include <vector>

#include "framework/core/parameters.h"
#include "framework/many_lights/clamp_compensation.h"
#include "framework/many_lights/light_paths.h"
#include "framework/many_lights/ray_scene.h"
#include "framework/many_lights/vpl_depth_maps.h"
#include "framework/many_lights/vpl_gather.h"
#include "framework/pipeline/indirect_method.h"
#include "framework/reference/mix64.h"

namespace lpvlab {

enum class VplVisibility { None, Rays, ShadowMaps, Imperfect };

// The name of a visibility for the manifest and for `visibility` keys.
std::string visibilityName(VplVisibility visibility);
// The `visibility` key of a method whose VPLs see by rays, shadow maps or not at all ("rays", the
// default; "shadow_maps"; "none").
VplVisibility readExactOrMappedVisibility(Params& p);

class VplMethod : public IndirectMethod {
public:
  std::vector<std::string> stageNames() const override;
  std::set<std::string> consumes() const override { return {}; }  // VPLs from rays
  void prepare(const MethodSetup& setup) override;
  void moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) override;
  void render(MethodFrame& frame) override;
  std::map<std::string, std::vector<WorkCount>> work() const override;
  std::size_t memoryBytes() const override;
  nlohmann::json statistics() const override;

  // The last frame's VPLs and their maps (empty without shadow maps), for tests.
  const std::vector<Vpl>& vpls() const { return vpls_; }
  const VplDepthMaps& depthMaps() const { return maps_; }

protected:
  // Reads the shared keys; `imperfect`: the points and pull-push levels of imperfect maps (read
  // by the subclass).
  VplMethod(Params& p, VplVisibility visibility, const ImperfectSettings& imperfect = {});

  // The frame's VPLs from the updated scene (the "vpls" stage).
  virtual void makeVpls(const RayScene& scene, std::vector<Vpl>& vpls) = 0;
  // The source's work (in the "vpls" stage) and its figures (merged into statistics()).
  virtual std::vector<WorkCount> sourceWork() const = 0;
  virtual nlohmann::json sourceStatistics() const = 0;

  // The most scatterings the light a VPL carries has had (1: VPLs where light first lands): the
  // depth of the light the clamp compensation adds back.
  virtual int vplBounces() const = 0;

  // The seed of imperfect maps' points and of the clamp compensation's paths (the subclass's
  // seed key).
  void setSeed(std::uint64_t seed) {
    imperfect_.seed = seed;
    compensation_.seed = mix64(seed ^ 0x636c616d70ull);  // "clamp": streams apart from the walks'
  }

private:
  VplVisibility visibility_;
  GatherSettings gather_;
  DepthMapSettings mapSettings_;
  ImperfectSettings imperfect_;
  std::unique_ptr<RayScene> scene_;
  std::unique_ptr<SurfacePointSampler> points_;
  std::vector<Vpl> vpls_;
  VplDepthMaps maps_;
  GatherCounts gatherCounts_;
  bool compensate_ = false;
  ClampCompensationSettings compensation_;
  ClampCompensationCounts compensationCounts_;
  std::size_t mapRays_ = 0;
  ImperfectCounts imperfectCounts_;
};

// VPLs from light paths each frame (light_paths.h): instant radiosity's source.
class LightPathMethod : public VplMethod {
protected:
  LightPathMethod(Params& p, VplVisibility visibility, const ImperfectSettings& imperfect = {});
  void makeVpls(const RayScene& scene, std::vector<Vpl>& vpls) override;
  int vplBounces() const override { return paths_.firstHitsOnly ? 1 : paths_.maxBounces; }
  std::vector<WorkCount> sourceWork() const override;
  nlohmann::json sourceStatistics() const override;

private:
  LightPathSettings paths_;
  LightPathCounts counts_;
};

}  // namespace lpvlab
