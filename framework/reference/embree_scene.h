#pragma once
// The scene's triangles in Embree 3: one device, one triangle geometry per non-empty mesh (its
// geomID indexes the records below), built with high quality for fast traversal. Alpha-masked
// textured materials get an intersection filter and an occlusion filter that reject hits where
// the base colour texture's alpha is below the cutoff, so camera, continuation and shadow rays
// all pass through the cut-out parts. The device's instruction set and query width come from
// RayEngineSettings (framework/reference/embree_device.h).

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "framework/reference/embree_device.h"
#include "framework/reference/material_sampling.h"
#include "framework/reference/ray_packets.h"
#include "framework/scene/scene.h"

namespace lpvlab {

// Per triangle, precomputed so that a hit needs no square root for its normals.
struct TriangleFrame {
  glm::vec3 unitNormal;  // geometric, as wound
  bool flat;             // all vertex normals are +-unitNormal: the shading normal is geometric
};

// What a hit on geometry geomID needs; the pointers are into the Scene and the materials, which
// must outlive the EmbreeScene, and into the EmbreeScene's own triangle frames.
struct GeometryRecord {
  const glm::vec3* normals;
  const glm::vec2* uvs;
  const glm::vec3* colors;  // vertex colours (Mesh::colors); null: none
  const std::uint32_t* indices;
  const TriangleFrame* triangles;
  const SurfaceMaterial* material;
  int meshIndex;  // into Scene::meshes
};

// An alpha lookup for alpha-masked materials other than the level-0 one (cutOut,
// material_sampling.h), for one query: the raster passes' (GL's alpha test reads the mip level of
// the pixel's footprint, framework/raster). `rayId` is the id the ray was set with.
class AlphaLookup {
public:
  virtual ~AlphaLookup() = default;
  virtual float alpha(const GeometryRecord& geometry, unsigned primID, float u, float v,
                      unsigned rayId) const = 0;
};

class EmbreeScene {
public:
  // Throws an Error for a scene without triangles or with a mesh whose attributes don't match
  // its positions or whose indices or material are out of range.
  // Also throws the errors of makeEmbreeDevice for bad engine settings. `include`, when given,
  // picks the meshes traced (the raster passes leave out some, as GL's draws do); an Error when
  // it leaves no triangle.
  EmbreeScene(const Scene& scene, const std::vector<SurfaceMaterial>& materials,
              const RayEngineSettings& engine = {},
              const std::function<bool(const Mesh&)>& include = {});

  const GeometryRecord& geometry(unsigned geomID) const { return records_[geomID]; }
  // Scene-scaled distance for ray offsets and shadow-ray ends: far above float rounding of the
  // scene's coordinates, far below any feature size (1e-4 of the largest coordinate or extent).
  float epsilon() const { return epsilon_; }

  // The instruction set Embree runs and the rays per query (see embree_device.h).
  const std::string& isa() const { return device_.isa; }
  int packetWidth() const { return device_.packetWidth; }

  // Nearest hits of the packet's active rays (each along origin + t direction, t in
  // (tnear, tfar)); `coherent` tells Embree the rays are similar (camera rays). `alpha`: alpha
  // masks cut where it says (null: at the texture's level 0).
  void intersect(RayPacket& packet, bool coherent, const AlphaLookup* alpha = nullptr) const;
  // Whether anything blocks each active ray of the packet.
  void occluded(ShadowPacket& packet, const AlphaLookup* alpha = nullptr) const;

private:
  struct ReleaseScene {
    void operator()(RTCScene scene) const { rtcReleaseScene(scene); }
  };
  EmbreeDevice device_;  // declared first: released last
  std::unique_ptr<RTCSceneTy, ReleaseScene> scene_;
  std::vector<GeometryRecord> records_;                // by geomID
  std::vector<std::vector<TriangleFrame>> triangles_;  // by geomID, then primID
  float epsilon_ = 0.0f;
};

// A vertex attribute at barycentrics (u, v) of the triangle with these corners (Embree's:
// point = (1 - u - v) p0 + u p1 + v p2).
template <class T>
T atBarycentrics(const T* values, const std::uint32_t* corner, float u, float v) {
  return (1.0f - u - v) * values[corner[0]] + u * values[corner[1]] + v * values[corner[2]];
}

// A ray's hit on the scene's surface.
struct SurfacePoint {
  glm::vec3 position;
  glm::vec3 geometricNormal;  // unit, as wound (either side)
  glm::vec3 shadingNormal;    // unit, turned to the side the ray came from
  glm::vec2 uv;               // zero for untextured materials (never read)
  glm::vec3 color{1.0f};      // the vertex colours interpolated; white for a mesh without
  const GeometryRecord* geometry;
};

// The point `hit` of the ray origin + t direction, with its shading normal (the vertex normals
// interpolated, the geometric one where they cancel), texture coordinates and vertex colour.
SurfacePoint surfaceAt(const EmbreeScene& scene, const RayHit& hit, const glm::vec3& origin,
                       const glm::vec3& direction);

// The Lambertian albedo at x: the material's (base colour x texture) times the vertex colour,
// as the raster passes compute it (shaders/raster/gbuffer.frag, rsm.frag).
inline glm::vec3 surfaceAlbedo(const SurfacePoint& x) {
  return albedoAt(*x.geometry->material, x.uv) * x.color;
}

// Start of a ray leaving x along `direction`: moved off the surface along the geometric normal,
// to the side the ray leaves on, so it cannot hit x's own triangle again.
inline glm::vec3 offsetRayOrigin(const EmbreeScene& scene, const SurfacePoint& x,
                                 const glm::vec3& direction) {
  const float side = glm::dot(x.geometricNormal, direction) > 0.0f ? 1.0f : -1.0f;
  return x.position + (side * scene.epsilon()) * x.geometricNormal;
}

}  // namespace lpvlab
