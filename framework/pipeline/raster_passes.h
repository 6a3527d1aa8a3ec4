#pragma once
// The rasterised stages every LPV variant stands on: the camera's G-buffer, and per light view
// the shadow map and the reflective shadow map.

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/extra_geometry.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/light_views.h"
#include "framework/pipeline/scene_gpu.h"

namespace lpvlab {

// Binds `framebuffer` for drawing the scene into its first `colourTargets` colour attachments
// (0: depth only): viewport, depth test (less), two-sided, colours cleared to 0, depth to 1.
// Strategies that rasterise the scene themselves (e.g. injection "sky_columns") start with it.
void beginRaster(const gl::Framebuffer& framebuffer, int width, int height, int colourTargets);

// The camera's view and projection for an image of width x height (vertical FOV, aspect =
// width / height): the G-buffer's, and that of any pass that must see exactly what it sees.
glm::mat4 cameraClipFromWorld(const Camera& camera, int width, int height);

// Allocates `maps`' RSM textures (position, normal, flux, depth; `views` layers of resolution^2,
// labelled "<label> position" etc.) and returns one framebuffer per layer drawing into them: the
// light maps' RSMs, and any strategy's own RSM (e.g. rendering "subsurface").
std::vector<gl::Framebuffer> allocateRsm(LightMaps& maps, int resolution, int views,
                                         const std::string& label);

class GBufferPass {
public:
  // emissive: some material of the scene emits. Without, the emission image stays zeros and is
  // never rendered (a colour target less for the rasteriser, an image less to read back).
  GBufferPass(ShaderCompiler& shaders, int width, int height, bool emissive = true);
  // Renders the scene and the extras from the camera (vertical FOV, aspect = width / height).
  void render(const SceneGpu& scene, const Camera& camera,
              const std::vector<const ExtraGeometry*>& extras = {});
  const GBuffer& gbuffer() const { return gbuffer_; }
  glm::mat4 clipFromWorld(const Camera& camera) const;

private:
  Program program_;
  GBuffer gbuffer_;
  std::optional<gl::Framebuffer> framebuffer_;  // none without GL
};

class LightMapsPass {
public:
  LightMapsPass(ShaderCompiler& shaders, const LightViews& views, int rsmResolution,
                int shadowResolution);
  void renderShadowMaps(const SceneGpu& scene, const std::vector<const ExtraGeometry*>& extras = {});
  void renderRsms(const SceneGpu& scene, const std::vector<const ExtraGeometry*>& extras = {});
  // The lights moved (an animation): the same lights and views, placed anew. Throws if the count
  // of lights or views differs from the maps'.
  void setViews(const LightViews& views);
  const LightMaps& lightMaps() const { return maps_; }

private:
  Program depthOnlyProgram_;  // shadows of surfaces without alpha masks
  Program shadowProgram_;     // shadows of alpha-masked surfaces (the material's alpha test)
  Program rsmProgram_;
  std::vector<glm::mat4> clipFromWorld_;  // per view
  LightMaps maps_;
  std::vector<gl::Framebuffer> shadowFramebuffers_, rsmFramebuffers_;  // per view (layer)
};

}  // namespace lpvlab
