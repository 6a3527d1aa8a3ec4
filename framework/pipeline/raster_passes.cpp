#include "framework/pipeline/raster_passes.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "framework/core/error.h"
#include "framework/gl/context.h"
#include "framework/math/view_matrix.h"

namespace lpvlab {

namespace gbuffer_kernel {
#include "shaders/raster/gbuffer_interface.glsl"
}
namespace rsm_kernel {
#include "shaders/common/light_records_interface.glsl"
#include "shaders/raster/rsm_interface.glsl"
}
using scene_vertex::LOCATION_CLIP_FROM_WORLD;

void beginRaster(const gl::Framebuffer& framebuffer, int width, int height, int colourTargets) {
  framebuffer.bind();
  static const GLenum targets[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                    GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  if (colourTargets > 0) glNamedFramebufferDrawBuffers(framebuffer.id(), colourTargets, targets);
  else glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // surfaces are two-sided
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 0; i < colourTargets; ++i) glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, i, zero);
  const float far = 1.0f;
  glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far);
}

GBufferPass::GBufferPass(ShaderCompiler& shaders, int width, int height, bool emissive) {
  gbuffer_.width = width;
  gbuffer_.height = height;
  gbuffer_.emissive = emissive;
  gbuffer_.position = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, "gbuffer position");
  gbuffer_.normal = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, "gbuffer normal");
  gbuffer_.albedo = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, "gbuffer albedo");
  gbuffer_.emission = gl::Texture(GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, "gbuffer emission");
  gbuffer_.depth = gl::Texture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height, 1, "gbuffer depth");
  // Without GL the textures only name the host's images (host_raster.h): nothing draws here.
  if (!GlContext::glLoaded()) return;
  program_ = shaders.graphics("raster/scene.vert", "raster/gbuffer.frag");
  framebuffer_.emplace();
  framebuffer_->attach(GL_COLOR_ATTACHMENT0, gbuffer_.position);
  framebuffer_->attach(GL_COLOR_ATTACHMENT1, gbuffer_.normal);
  framebuffer_->attach(GL_COLOR_ATTACHMENT2, gbuffer_.albedo);
  if (emissive) {
    framebuffer_->attach(GL_COLOR_ATTACHMENT3, gbuffer_.emission);
  } else {
    // Not a target: gbuffer.frag's fourth output goes nowhere, and direct light reads zeros.
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(gbuffer_.emission.id(), 0, GL_RGBA, GL_FLOAT, zero);
  }
  framebuffer_->attach(GL_DEPTH_ATTACHMENT, gbuffer_.depth);
  framebuffer_->checkComplete("G-buffer");
}

glm::mat4 cameraClipFromWorld(const Camera& camera, int width, int height) {
  const glm::mat4 view = viewFromWorld(camera.position, camera.forward, camera.up);
  const glm::mat4 clipFromView = glm::perspective(camera.verticalFov, float(width) / float(height),
                                                  camera.nearPlane, camera.farPlane);
  return clipFromView * view;
}

glm::mat4 GBufferPass::clipFromWorld(const Camera& camera) const {
  return cameraClipFromWorld(camera, gbuffer_.width, gbuffer_.height);
}

void GBufferPass::render(const SceneGpu& scene, const Camera& camera,
                         const std::vector<const ExtraGeometry*>& extras) {
  if (!GlContext::glLoaded()) gl::noGl("the G-buffer by rasterisation");
  beginRaster(*framebuffer_, gbuffer_.width, gbuffer_.height, gbuffer_.emissive ? 4 : 3);
  program_.use();
  const glm::mat4 clip = clipFromWorld(camera);
  glUniformMatrix4fv(LOCATION_CLIP_FROM_WORLD, 1, GL_FALSE, &clip[0][0]);
  glUniform3fv(gbuffer_kernel::LOCATION_CAMERA_POSITION, 1, &camera.position[0]);
  glUniform3fv(gbuffer_kernel::LOCATION_CAMERA_FORWARD, 1, &camera.forward[0]);
  scene.draw();
  const RasterView view{.target = RasterTarget::GBuffer,
                        .clipFromWorld = clip,
                        .viewer = glm::vec4(camera.position, 1.0f),
                        .cameraPosition = camera.position,
                        .cameraForward = camera.forward};
  for (const ExtraGeometry* extra : extras) extra->draw(view);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<gl::Framebuffer> allocateRsm(LightMaps& maps, int resolution, int views,
                                         const std::string& label) {
  const int r = resolution;
  // A scene lit only by emissive surfaces (a method that reads them, e.g. radiosity) has no
  // view: one layer is kept so the textures exist for the shaders' bindings; nothing draws into
  // it, and every reader stops at `views`.
  const int layers = std::max(views, 1);
  maps.rsmPosition = gl::Texture(GL_TEXTURE_2D_ARRAY, GL_RGBA32F, r, r, layers, label + " position");
  maps.rsmNormal = gl::Texture(GL_TEXTURE_2D_ARRAY, GL_RGBA32F, r, r, layers, label + " normal");
  maps.rsmFlux = gl::Texture(GL_TEXTURE_2D_ARRAY, GL_RGBA32F, r, r, layers, label + " flux");
  maps.rsmDepth = gl::Texture(GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, r, r, layers, label + " depth");
  if (!GlContext::glLoaded()) return {};  // the host's images alone (host_raster.h)
  std::vector<gl::Framebuffer> framebuffers(static_cast<std::size_t>(views));
  for (int layer = 0; layer < views; ++layer) {
    gl::Framebuffer& fb = framebuffers[static_cast<std::size_t>(layer)];
    fb.attach(GL_COLOR_ATTACHMENT0, maps.rsmPosition, layer);
    fb.attach(GL_COLOR_ATTACHMENT1, maps.rsmNormal, layer);
    fb.attach(GL_COLOR_ATTACHMENT2, maps.rsmFlux, layer);
    fb.attach(GL_DEPTH_ATTACHMENT, maps.rsmDepth, layer);
    fb.checkComplete(label + " layer " + std::to_string(layer));
  }
  return framebuffers;
}

LightMapsPass::LightMapsPass(ShaderCompiler& shaders, const LightViews& views, int rsmResolution,
                             int shadowResolution) {
  const int layers = int(views.views.size());
  maps_.views = layers;
  maps_.lightCount = int(views.lights.size());
  maps_.rsmResolution = rsmResolution;
  maps_.shadowResolution = shadowResolution;
  const int r = rsmResolution, s = shadowResolution;
  rsmFramebuffers_ = allocateRsm(maps_, r, layers, "rsm");
  maps_.shadowDepth =
      gl::Texture(GL_TEXTURE_2D_ARRAY, GL_DEPTH_COMPONENT32F, s, s, std::max(layers, 1), "shadow maps");
  maps_.lightRecords = gl::Buffer(std::max<size_t>(1, views.lights.size()) * sizeof(GpuLight),
                                  "light records", nullptr);
  maps_.viewRecords = gl::Buffer(std::max<size_t>(1, views.views.size()) * sizeof(GpuView),
                                 "view records", nullptr);
  setViews(views);
  // Without GL the textures only name the host's images (host_raster.h): nothing draws here.
  if (!GlContext::glLoaded()) return;
  depthOnlyProgram_ = shaders.graphics("raster/scene.vert", "raster/depth_only.frag");
  shadowProgram_ = shaders.graphics("raster/scene.vert", "raster/shadow.frag");
  rsmProgram_ = shaders.graphics("raster/scene.vert", "raster/rsm.frag");
  // Hardware depth comparison with bilinear filtering: each shadow tap is a 2x2 PCF.
  glTextureParameteri(maps_.shadowDepth.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(maps_.shadowDepth.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTextureParameteri(maps_.shadowDepth.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(maps_.shadowDepth.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(maps_.shadowDepth.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(maps_.shadowDepth.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  for (int layer = 0; layer < layers; ++layer) {
    gl::Framebuffer& shadow = shadowFramebuffers_.emplace_back();
    shadow.attach(GL_DEPTH_ATTACHMENT, maps_.shadowDepth, layer);
    glNamedFramebufferDrawBuffer(shadow.id(), GL_NONE);
    glNamedFramebufferReadBuffer(shadow.id(), GL_NONE);
    shadow.checkComplete("shadow map layer " + std::to_string(layer));
  }
}

void LightMapsPass::setViews(const LightViews& views) {
  if (int(views.views.size()) != maps_.views || int(views.lights.size()) != maps_.lightCount)
    throw Error("light maps: the lights changed in number or kind (only moves are updated)");
  clipFromWorld_.clear();
  for (const GpuView& view : views.views) clipFromWorld_.push_back(view.clipFromWorld);
  maps_.records = views;
  if (!views.lights.empty())
    maps_.lightRecords.upload(views.lights.data(), views.lights.size() * sizeof(GpuLight));
  if (!views.views.empty())
    maps_.viewRecords.upload(views.views.data(), views.views.size() * sizeof(GpuView));
}

// Surfaces without alpha masks go through a fragment-free program, the alpha-masked ones through
// the material's alpha test; the depth test keeps the nearest either way, so the map is the same.
void LightMapsPass::renderShadowMaps(const SceneGpu& scene, const std::vector<const ExtraGeometry*>& extras) {
  if (!GlContext::glLoaded()) gl::noGl("shadow maps by rasterisation");
  for (int layer = 0; layer < maps_.views; ++layer) {
    beginRaster(shadowFramebuffers_[layer], maps_.shadowResolution, maps_.shadowResolution, 0);
    depthOnlyProgram_.use();
    glUniformMatrix4fv(LOCATION_CLIP_FROM_WORLD, 1, GL_FALSE, &clipFromWorld_[layer][0][0]);
    scene.draw(SceneGpu::AlphaMasks::None, false);
    shadowProgram_.use();
    glUniformMatrix4fv(LOCATION_CLIP_FROM_WORLD, 1, GL_FALSE, &clipFromWorld_[layer][0][0]);
    scene.draw(SceneGpu::AlphaMasks::Only);
    const RasterView view{.target = RasterTarget::ShadowMap,
                          .clipFromWorld = clipFromWorld_[layer],
                          .viewer = lightViewViewer(maps_.records, layer)};
    for (const ExtraGeometry* extra : extras) extra->draw(view);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void LightMapsPass::renderRsms(const SceneGpu& scene, const std::vector<const ExtraGeometry*>& extras) {
  if (!GlContext::glLoaded()) gl::noGl("RSMs by rasterisation");
  using namespace rsm_kernel;
  maps_.lightRecords.bindStorage(BUFFER_LIGHTS);
  maps_.viewRecords.bindStorage(BUFFER_VIEWS);
  for (int layer = 0; layer < maps_.views; ++layer) {
    beginRaster(rsmFramebuffers_[layer], maps_.rsmResolution, maps_.rsmResolution, 3);
    rsmProgram_.use();  // again for each view: an extra may have bound its own program
    glUniform1i(LOCATION_RESOLUTION, maps_.rsmResolution);
    glUniformMatrix4fv(LOCATION_CLIP_FROM_WORLD, 1, GL_FALSE, &clipFromWorld_[layer][0][0]);
    glUniform1i(LOCATION_VIEW_INDEX, layer);
    scene.draw(SceneGpu::AlphaMasks::Any, true, /*injectingOnly=*/true);
    const RasterView view{.target = RasterTarget::Rsm,
                          .clipFromWorld = clipFromWorld_[layer],
                          .viewer = lightViewViewer(maps_.records, layer),
                          .viewIndex = layer,
                          .resolution = maps_.rsmResolution};
    for (const ExtraGeometry* extra : extras) extra->draw(view);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::size_t GBuffer::memoryBytes() const {
  return position.bytes() + normal.bytes() + albedo.bytes() + emission.bytes() + depth.bytes();
}

std::size_t LightMaps::memoryBytes() const {
  return rsmPosition.bytes() + rsmNormal.bytes() + rsmFlux.bytes() + rsmDepth.bytes() +
         shadowDepth.bytes() + lightRecords.size() + viewRecords.size();
}

}  // namespace lpvlab
