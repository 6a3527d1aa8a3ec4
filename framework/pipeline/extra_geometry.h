#pragma once
// Geometry the raster passes draw beside the scene's meshes with programs of their own: the
// light-field billboards of particle systems (framework/particles/particle_billboards.h). The
// camera's G-buffer and each light view's shadow map and RSM draw the scene, then every extra
// with what the pass is drawing and from where, into the framebuffer the pass has bound (its
// depth test keeps the nearest surface of either). Strategies that rasterise the scene on their
// own (the subsurface RSM, sky injection's columns) see the scene's meshes only.

#include <glm/glm.hpp>

namespace lpvlab {

enum class RasterTarget { GBuffer, ShadowMap, Rsm };

struct RasterView {
  RasterTarget target = RasterTarget::GBuffer;
  glm::mat4 clipFromWorld{1.0f};
  // Where the pass looks from: a position (w = 1; the camera, a point or spot light) or the
  // unit direction towards a directional light (w = 0).
  glm::vec4 viewer{0.0f, 0.0f, 0.0f, 1.0f};
  // GBuffer: the camera (raster/gbuffer_output.glsl turns normals to it and stores view depth).
  glm::vec3 cameraPosition{0.0f}, cameraForward{0.0f, 0.0f, -1.0f};
  // Rsm: the light view and its resolution (raster/rsm_output.glsl; the pass has bound the
  // light and view records).
  int viewIndex = 0;
  int resolution = 0;
};

class ExtraGeometry {
public:
  virtual ~ExtraGeometry() = default;
  virtual void draw(const RasterView& view) const = 0;
};

}  // namespace lpvlab
