#pragma once
// What one frame's stages read and write. The pipeline owns all of it; strategies get a Frame.

#include <span>

#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/pipeline/dual_image.h"
#include "framework/pipeline/host_readback.h"
#include "framework/pipeline/light_grid.h"
#include "framework/pipeline/light_views.h"
#include "framework/pipeline/named_resources.h"

namespace lpvlab {

// The camera's view of the scene, one texel per output pixel (textures are bottom row first,
// as GL has them). Uncovered pixels have position.w = 0.
struct GBuffer {
  int width = 0, height = 0;
  gl::Texture position;   // RGBA32F: world position (m), w = 1 where a surface was hit
  gl::Texture normal;     // RGBA32F: unit world normal facing the camera, w = view depth (m)
  gl::Texture albedo;     // RGBA32F: Lambertian reflectance
  gl::Texture emission;   // RGBA32F: emitted radiance, W/(m^2 sr); zeros unless `emissive`
  bool emissive = true;   // some material emits: emission is rendered (else never written)
  gl::Texture depth;      // DEPTH32F: the rasteriser's depth buffer
  std::size_t memoryBytes() const;
};

// Per light view (a cube face of a point or spot light, or a directional light's box): the
// shadow map for direct light and the reflective shadow map (RSM) for injection, as 2D array
// textures with one layer per view. Views and lights are described to kernels by the GPU
// records in light_views.h.
struct LightMaps {
  int views = 0;
  int rsmResolution = 0;
  int shadowResolution = 0;
  gl::Texture rsmPosition;  // RGBA32F: world position of the texel's surface, w = 1 if covered
  gl::Texture rsmNormal;    // RGBA32F: unit normal facing the light
  gl::Texture rsmFlux;      // RGBA32F: reflected flux of the texel's surface patch, W per channel
  gl::Texture rsmDepth;     // DEPTH32F
  gl::Texture shadowDepth;  // DEPTH32F, shadowResolution^2 per layer
  gl::Buffer lightRecords;  // GpuLight[] (bound where shaders/common/light_records_interface.glsl says)
  gl::Buffer viewRecords;   // GpuView[]
  LightViews records;       // the host's copy of both, for CPU kernels
  int lightCount = 0;
  std::size_t memoryBytes() const;
};

class SceneGpu;
struct Camera;

// With cascades ([cascades] levels > 1, framework/pipeline/cascade.h) occlusion, injection and
// propagation are called once per level, with the lightGrid and the resources of that level;
// rendering is called once and reads every level.
struct Frame {
  const SceneGpu* scene = nullptr;      // for strategies that rasterise the scene themselves
  const Camera* camera = nullptr;
  const GBuffer& gbuffer;
  const LightMaps& lightMaps;
  LightGrid& lightGrid;                 // the level being filled
  DualImage& indirect;  // output of rendering, zeros when it starts: indirect radiance, W/(m^2 sr)
  const ResourceTable* resources = nullptr;  // the level's resources (named_resources.h)
  HostReadback* host = nullptr;  // the raster passes' images on the CPU, read once per frame
  std::span<LightGrid> levels;               // every level, finest first; empty: lightGrid alone
  float cascadeBlendCells = 0.0f;            // [cascades] blend_cells
  int level = 0;                             // the level being filled, 0 the finest
  // Counts the moves of the scene's geometry in this run (Pipeline::moveScene): a strategy that
  // keeps data about surfaces between frames starts anew when it changes.
  int geometryVersion = 0;

  // The level's resource of that key, or null when the run has none.
  template <class T>
  T* find(const ResourceKey<T>& key) const {
    return resources ? resources->find(key) : nullptr;
  }
  // The level's resource of that key, which the strategy consumes (an Error when missing).
  template <class T>
  T& get(const ResourceKey<T>& key) const {
    static const ResourceTable none;  // a frame without resources has none of any name
    return (resources ? *resources : none).get(key);
  }

  // What rendering reads: every level, finest first (one level without cascades).
  std::span<const LightGrid> renderedLevels() const {
    return levels.empty() ? std::span<const LightGrid>(&lightGrid, 1) : std::span<const LightGrid>(levels);
  }
};

}  // namespace lpvlab
