#pragma once
// The patches in Embree: what the ray-cast form factors, the lights' first shot and the display
// trace. One mesh per scene mesh holds its patches as separate triangles (patch k of the mesh is
// its primitive k), with the scene's materials made opaque (radiosity ignores alpha masks, as the
// hemicube does).

#include <cstddef>
#include <memory>
#include <vector>

#include "framework/radiosity/patches.h"
#include "framework/reference/embree_scene.h"

namespace lpvlab {

class PatchRayScene {
public:
  PatchRayScene(const Scene& scene, const PatchMesh& mesh);

  const EmbreeScene& embree() const { return *embree_; }
  // The patch a ray hit.
  std::size_t patchOf(const RayHit& hit) const {
    return firstPatch_[std::size_t(embree_->geometry(hit.geomID).meshIndex)] + hit.primID;
  }
  std::size_t memoryBytes() const;

private:
  Scene scene_;
  std::vector<SurfaceMaterial> materials_;
  std::unique_ptr<EmbreeScene> embree_;
  std::vector<std::size_t> firstPatch_;  // per mesh of scene_
};

}  // namespace lpvlab
