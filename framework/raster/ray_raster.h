#pragma once
// The raster passes by ray casting with Embree ([compute] raster = "embree"; HostRaster): one
// ray through each texel centre of the camera's and every light view's image, its nearest hit
// shaded by the fragment shaders' own arithmetic compiled as C++ (shaders/raster/gbuffer_texel.glsl,
// rsm_texel.glsl). What GL's passes draw is what is traced: the meshes GL rasterises
// (Mesh::rasterised), the RSMs only those whose material injects (Material::injects), alpha
// masks cutting surfaces out (EmbreeScene's filters). Base colour textures, and the alpha the
// masks test, are sampled as GL's sampler does: trilinearly from a mip chain at the level of
// detail of the texel's footprint (texture_mips.h), its derivatives from the neighbouring texels'
// rays met with the hit triangle's plane. Shadow rays have no footprint: they test alpha at level
// 0, as the path tracer does.
//
// Each texel is written by one task, so the images do not depend on the thread count. Rays go to
// Embree 16 at a time, 4 x 4 texels of a tile, flagged coherent.

#include <memory>
#include <string>
#include <vector>

#include "framework/pipeline/host_raster.h"
#include "framework/raster/texture_mips.h"
#include "framework/raster/view_rays.h"
#include "framework/reference/embree_scene.h"

namespace lpvlab {

class RayRaster final : public HostRaster {
public:
  // Copies the scene (its meshes, materials and textures: the raster passes outlive the caller's
  // scene) and builds its BVHs. Throws an Error for a scene the path tracer would refuse (no
  // triangle drawn, a mesh whose attributes don't match its positions) or engine settings this
  // CPU cannot run.
  explicit RayRaster(const Scene& scene, const RayEngineSettings& engine = {});

  std::string name() const override { return "embree"; }
  nlohmann::json report() const override;
  void renderGBuffer(const Camera& camera, const glm::mat4& clipFromWorld,
                     const HostGBufferTargets& out) override;
  void renderShadowMaps(const LightViews& views, int resolution, HostDepthImage& out) override;
  void renderRsms(const LightViews& views, int resolution, const HostRsmTargets& out) override;
  // Rays from each surface point moved epsilon() along its normal, to a point or spot light's
  // position (stopping epsilon() short) or towards a directional light without end; surfaces
  // facing away from a light get 0 without a ray.
  void shadowRays(const HostImage& position, const HostImage& normal, const LightViews& views,
                  std::vector<float>& visibility) override;
  void moveGeometry(const Scene& scene) override;
  // Host bytes of its copy of the scene (textures included; the BVHs are Embree's, not counted).
  std::size_t memoryBytes() const override;

private:
  // A surface point a texel's ray hit, with the vertex attributes GL interpolates for fragments.
  struct TexelSurface {
    glm::vec3 position;
    glm::vec3 normal;  // the vertex normals interpolated, not normalised (the shaders normalise)
    glm::vec3 albedo;  // material x texture (mip-mapped) x vertex colour
    const GeometryRecord* geometry;
  };
  TexelSurface surfaceOf(const EmbreeScene& scene, const ViewRays& rays, int x, int y,
                         const ViewRay& ray, const RayHit& hit) const;
  // The base colour texture of g's material, linear RGBA, at barycentrics (u, v) of triangle
  // primID, at the level of detail of texel (x, y) of `rays`.
  glm::vec4 textureAt(const GeometryRecord& g, unsigned primID, float u, float v,
                      const ViewRays& rays, int x, int y) const;
  // Its texture's mip chain, uv and level of detail there (textureAt's lookup without the lookup).
  struct TextureLookup {
    const MipChain* mips;
    glm::vec2 uv;
    float lod;
  };
  TextureLookup lookupAt(const GeometryRecord& g, unsigned primID, float u, float v,
                         const ViewRays& rays, int x, int y) const;
  class ViewAlpha;  // alpha masks at the texel's level of detail, for Embree's filter
  void build();

  Scene scene_;
  RayEngineSettings engine_;
  std::vector<SurfaceMaterial> materials_;     // into scene_'s textures
  std::vector<std::unique_ptr<MipChain>> mips_;  // per texture of scene_
  std::unique_ptr<EmbreeScene> drawn_;         // every rasterised mesh: G-buffer, shadow maps
  std::unique_ptr<EmbreeScene> injecting_;     // those whose material injects, when some doesn't
  const EmbreeScene* rsmScene_ = nullptr;      // drawn_ or injecting_; null: nothing injects
  double buildMs_ = 0.0;                       // the last build of the BVHs
};

}  // namespace lpvlab
