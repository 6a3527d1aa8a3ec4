#version 450
// Direct light at every G-buffer pixel (direct_light.glsl, shared with the CPU kernel).
#include "../common/lights_gpu.glsl"

#include "direct_interface.glsl"
#include "../common/light_records_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;

layout(binding = UNIT_G_POSITION) uniform sampler2D gPosition;
layout(binding = UNIT_G_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_G_ALBEDO) uniform sampler2D gAlbedo;
layout(binding = UNIT_G_EMISSION) uniform sampler2D gEmission;
layout(binding = UNIT_SHADOW_MAPS) uniform sampler2DArrayShadow shadowMaps;  // LINEAR, LEQUAL
layout(binding = IMAGE_OUT_DIRECT, rgba32f) uniform writeonly image2D outDirect;

layout(std430, binding = BUFFER_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = BUFFER_VIEWS) readonly buffer Views { GpuView views[]; };
layout(location = LOCATION_LIGHT_COUNT) uniform int lightCount;
layout(location = LOCATION_SHADOW_RESOLUTION) uniform int shadowResolution;
layout(location = LOCATION_NORMAL_OFFSET_TEXELS) uniform float normalOffsetTexels;  // shadow-acne bias along the normal
layout(location = LOCATION_DEPTH_BIAS) uniform float depthBias;           // in window depth units

GpuLight directLight(int i) { return lights[i]; }
GpuView directView(int v) { return views[v]; }
// Nine taps of the texture unit's 2x2 PCF.
float shadowTaps3x3(int view, vec2 uv, float reference) {
  float texel = 1.0 / float(shadowResolution);
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += texture(shadowMaps, vec4(uv + vec2(x, y) * texel, float(view), reference));
  return lit / 9.0;
}
#include "direct_light.glsl"

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(outDirect)))) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) {
    imageStore(outDirect, pixel, vec4(0.0));
    return;
  }
  vec3 radiance = directRadiance(position.xyz, texelFetch(gNormal, pixel, 0).xyz,
                                 texelFetch(gAlbedo, pixel, 0).rgb,
                                 texelFetch(gEmission, pixel, 0).rgb, lightCount,
                                 shadowResolution, normalOffsetTexels, depthBias);
  imageStore(outDirect, pixel, vec4(radiance, 1.0));
}
