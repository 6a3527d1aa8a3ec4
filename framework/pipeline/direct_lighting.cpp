#include "framework/pipeline/direct_lighting.h"

#include "framework/gl/dispatch.h"

namespace lpvlab {

DirectLighting::DirectLighting(ShaderCompiler& shaders, ShadowSettings settings)
    : program_(shaders.compute("lighting/direct.comp")), settings_(settings) {}

void DirectLighting::render(const GBuffer& gbuffer, const LightMaps& maps, gl::Texture& direct) {
  program_.use();
  glBindTextureUnit(0, gbuffer.position.id());
  glBindTextureUnit(1, gbuffer.normal.id());
  glBindTextureUnit(2, gbuffer.albedo.id());
  glBindTextureUnit(3, gbuffer.emission.id());
  glBindTextureUnit(4, maps.shadowDepth.id());
  glBindImageTexture(0, direct.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  maps.lightRecords.bindStorage(1);
  maps.viewRecords.bindStorage(2);
  glUniform1i(0, maps.lightCount);
  glUniform1i(1, maps.shadowResolution);
  glUniform1f(2, settings_.normalOffsetTexels);
  glUniform1f(3, settings_.depthBias);
  dispatchCovering({gbuffer.width, gbuffer.height, 1}, {8, 8, 1}, GL_ALL_BARRIER_BITS);
}

}  // namespace lpvlab
