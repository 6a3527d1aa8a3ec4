#include "framework/pipeline/direct_lighting.h"

#include <algorithm>

#include "framework/core/error.h"
#include "framework/gl/dispatch.h"
#include "framework/pipeline/direct_lighting_cpu.h"

namespace lpvlab {

namespace direct_kernel {
#include "shaders/common/light_records_interface.glsl"
#include "shaders/lighting/direct_interface.glsl"
}

DirectLighting::DirectLighting(ShaderCompiler& shaders, ShadowSettings settings, bool onCpu,
                               HostRaster* shadowRays)
    : settings_(settings), onCpu_(onCpu), shadowRays_(shadowRays) {
  if (settings_.rays && (!onCpu_ || !shadowRays_))
    throw Error("key 'light_maps.shadows': \"rays\" are traced on the CPU, where direct light must "
                "then run: [compute] backend = \"cpu\", or \"auto\" on a software GL renderer");
  if (!onCpu_) program_ = shaders.compute("lighting/direct.comp");
}

void DirectLighting::render(const GBuffer& gbuffer, const LightMaps& maps, DualImage& direct,
                            HostReadback& host) {
  if (onCpu_) return renderOnCpu(gbuffer, maps, direct, host);
  using namespace direct_kernel;
  program_.use();
  glBindTextureUnit(UNIT_G_POSITION, gbuffer.position.id());
  glBindTextureUnit(UNIT_G_NORMAL, gbuffer.normal.id());
  glBindTextureUnit(UNIT_G_ALBEDO, gbuffer.albedo.id());
  glBindTextureUnit(UNIT_G_EMISSION, gbuffer.emission.id());
  glBindTextureUnit(UNIT_SHADOW_MAPS, maps.shadowDepth.id());
  glBindImageTexture(IMAGE_OUT_DIRECT, direct.texture().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  maps.lightRecords.bindStorage(BUFFER_LIGHTS);
  maps.viewRecords.bindStorage(BUFFER_VIEWS);
  glUniform1i(LOCATION_LIGHT_COUNT, maps.lightCount);
  glUniform1i(LOCATION_SHADOW_RESOLUTION, maps.shadowResolution);
  glUniform1f(LOCATION_NORMAL_OFFSET_TEXELS, settings_.normalOffsetTexels);
  glUniform1f(LOCATION_DEPTH_BIAS, settings_.depthBias);
  dispatchCovering({gbuffer.width, gbuffer.height, 1}, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                   GL_ALL_BARRIER_BITS);
}

// Per pixel and light: the shadow lookup's projection (16 multiply-adds) and the nine taps, which
// GL's texture unit takes as 9 x (4 comparisons and 3 interpolations) from 36 texels, and the CPU
// as one pass of 16 comparisons with separable weights (about 24) from 16 texels (4 B each);
// the light's falloff and cosine (about 15). Plus, per pixel, the G-buffer's four texels read and
// the result written (80 B), counted against each light.
//
// With shadow rays, per pixel and light one ray (its traversal is not multiply-adds: not counted)
// and the falloff and cosine; the G-buffer and the result as above.
WorkCount DirectLighting::work(double pixels, int lights, bool glKernel) const {
  const double perPixelBytes = 80.0 / std::max(1, lights);
  if (settings_.rays && !glKernel) return {"pixel-light", pixels * lights, 15.0, 4.0 + perPixelBytes};
  const bool cpu = onCpu_ && !glKernel;
  const double taps = cpu ? 24.0 : 9.0 * 7.0;
  const double texels = cpu ? 16.0 : 36.0;
  return {"pixel-light", pixels * lights, 16.0 + taps + 15.0, texels * 4.0 + perPixelBytes};
}

// The G-buffer and the shadow maps come from the frame's host copies (read back once per frame,
// shared with the CPU strategies); the image is written on its host side, which stays there
// until something on GL asks for it (dual_image.h).
void DirectLighting::renderOnCpu(const GBuffer& gbuffer, const LightMaps& maps, DualImage& direct,
                                 HostReadback& host) {
  gl::barrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // the raster passes, before reading them back
  const HostImage& position = host.image(gbuffer.position);
  const HostImage& normal = host.image(gbuffer.normal);
  if (settings_.rays) shadowRays_->shadowRays(position, normal, maps.records, visibility_);
  directLightingCpu({.position = &position,
                     .normal = &normal,
                     .albedo = &host.image(gbuffer.albedo),
                     .emission = gbuffer.emissive ? &host.image(gbuffer.emission) : nullptr,
                     .shadowDepth = settings_.rays ? nullptr : &host.depth(maps.shadowDepth),
                     .visibility = settings_.rays ? &visibility_ : nullptr,
                     .records = &maps.records,
                     .normalOffsetTexels = settings_.normalOffsetTexels,
                     .depthBias = settings_.depthBias},
                    direct.host());
}

}  // namespace lpvlab
