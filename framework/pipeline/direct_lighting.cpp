#include "framework/pipeline/direct_lighting.h"

#include "framework/gl/dispatch.h"

namespace lpvlab {

namespace direct_kernel {
#include "shaders/common/light_records_interface.glsl"
#include "shaders/lighting/direct_interface.glsl"
}

DirectLighting::DirectLighting(ShaderCompiler& shaders, ShadowSettings settings)
    : program_(shaders.compute("lighting/direct.comp")), settings_(settings) {}

void DirectLighting::render(const GBuffer& gbuffer, const LightMaps& maps, gl::Texture& direct) {
  using namespace direct_kernel;
  program_.use();
  glBindTextureUnit(UNIT_G_POSITION, gbuffer.position.id());
  glBindTextureUnit(UNIT_G_NORMAL, gbuffer.normal.id());
  glBindTextureUnit(UNIT_G_ALBEDO, gbuffer.albedo.id());
  glBindTextureUnit(UNIT_G_EMISSION, gbuffer.emission.id());
  glBindTextureUnit(UNIT_SHADOW_MAPS, maps.shadowDepth.id());
  glBindImageTexture(IMAGE_OUT_DIRECT, direct.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  maps.lightRecords.bindStorage(BUFFER_LIGHTS);
  maps.viewRecords.bindStorage(BUFFER_VIEWS);
  glUniform1i(LOCATION_LIGHT_COUNT, maps.lightCount);
  glUniform1i(LOCATION_SHADOW_RESOLUTION, maps.shadowResolution);
  glUniform1f(LOCATION_NORMAL_OFFSET_TEXELS, settings_.normalOffsetTexels);
  glUniform1f(LOCATION_DEPTH_BIAS, settings_.depthBias);
  dispatchCovering({gbuffer.width, gbuffer.height, 1}, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                   GL_ALL_BARRIER_BITS);
}

}  // namespace lpvlab
