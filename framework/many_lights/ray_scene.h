#pragma once
// The scene as the many-light methods trace it on the CPU: their own copy of the scene (Embree
// keeps pointers into its meshes and materials), its materials prepared for per-hit lookups, its
// triangles in Embree and its punctual lights. Moving lights replaces the lights; moving geometry
// copies the new vertices, and the next update() rebuilds Embree's scene (so a method can time
// the rebuild inside its frame).

#include <memory>
#include <vector>

#include "framework/reference/embree_scene.h"
#include "framework/reference/light_sampler.h"
#include "framework/scene/scene.h"

namespace lpvlab {

class RayScene {
public:
  // Embree's scene, lights and bounds are those of the last update() (or construction).
  // Throws the Errors of EmbreeScene and LightSampler (a scene without triangles, a light with
  // non-finite values, ...).
  explicit RayScene(const Scene& scene, const RayEngineSettings& engine = {});

  void moveLights(const Scene& scene);
  void moveGeometry(const Scene& scene);
  // Rebuilds what moveGeometry left out of date.
  void update();

  const EmbreeScene& embree() const { return *embree_; }
  const Scene& scene() const { return scene_; }  // the copy, with the last moves applied
  const std::vector<PunctualLight>& lights() const { return lights_->punctual(); }
  // The lights as the path tracer's next-event estimation reads them (clamp_compensation.h).
  const LightSampler& lightSampler() const { return *lights_; }
  const Bounds& bounds() const { return bounds_; }
  // Bytes of the copy's vertices, indices and textures (Embree's own BVH is not counted).
  std::size_t memoryBytes() const;

private:
  void build();

  RayEngineSettings engine_;
  Scene scene_;
  std::vector<SurfaceMaterial> materials_;
  std::unique_ptr<EmbreeScene> embree_;
  std::unique_ptr<LightSampler> lights_;
  Bounds bounds_;
  bool stale_ = false;
};

}  // namespace lpvlab
