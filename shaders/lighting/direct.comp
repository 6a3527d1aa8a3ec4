#version 450
// Direct light at every G-buffer pixel: Lambertian reflection of each light, shadow-mapped, plus
// the surface's own emission. Out: radiance, W/(m^2 sr).
//   L = emission + albedo / pi * sum over lights of E_light * visibility
//   point/spot: E = I * falloff * cos(theta) / r^2;  directional: E = E_perp * cos(theta)
#include "../common/lights_gpu.glsl"
#include "../common/lights.glsl"

#include "direct_interface.glsl"
#include "../common/light_records_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;

layout(binding = UNIT_G_POSITION) uniform sampler2D gPosition;
layout(binding = UNIT_G_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_G_ALBEDO) uniform sampler2D gAlbedo;
layout(binding = UNIT_G_EMISSION) uniform sampler2D gEmission;
layout(binding = UNIT_SHADOW_MAPS) uniform sampler2DArrayShadow shadowMaps;
layout(binding = IMAGE_OUT_DIRECT, rgba32f) uniform writeonly image2D outDirect;

layout(std430, binding = BUFFER_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = BUFFER_VIEWS) readonly buffer Views { GpuView views[]; };
layout(location = LOCATION_LIGHT_COUNT) uniform int lightCount;
layout(location = LOCATION_SHADOW_RESOLUTION) uniform int shadowResolution;
layout(location = LOCATION_NORMAL_OFFSET_TEXELS) uniform float normalOffsetTexels;  // shadow-acne bias along the normal
layout(location = LOCATION_DEPTH_BIAS) uniform float depthBias;           // in window depth units

int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x > 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y > 0.0 ? 2 : 3;
  return d.z > 0.0 ? 4 : 5;
}

int viewOfFace(GpuLight light, int face) {
  return face < 4 ? light.viewOfFace0123[face] : light.viewOfFace45[face - 4];
}

// Fraction of a 3x3 tap (each tap a bilinear 2x2 comparison) of the shadow map that sees p.
float visibility(int view, vec3 p) {
  vec4 clip = views[view].clipFromWorld * vec4(p, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  vec3 window = ndc * 0.5 + 0.5;
  float texel = 1.0 / float(shadowResolution);
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += texture(shadowMaps, vec4(window.xy + vec2(x, y) * texel, float(view),
                                      window.z - depthBias));
  return lit / 9.0;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(outDirect)))) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) {
    imageStore(outDirect, pixel, vec4(0.0));
    return;
  }
  vec3 p = position.xyz;
  vec3 n = texelFetch(gNormal, pixel, 0).xyz;
  vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
  vec3 irradiance = vec3(0.0);
  for (int i = 0; i < lightCount; ++i) {
    GpuLight light = lights[i];
    int type = int(light.positionType.w);
    vec3 toLight;
    vec3 e;
    int view;
    float texelWorld;
    if (type == LIGHT_DIRECTIONAL) {
      toLight = -light.directionCosOuter.xyz;
      e = light.intensityCosInner.rgb;
      view = light.viewOfFace0123.x;
      texelWorld = views[view].params.y / float(shadowResolution);
    } else {
      vec3 d = light.positionType.xyz - p;
      float r2 = max(dot(d, d), 1e-12);
      toLight = d * inversesqrt(r2);
      float falloff = type == LIGHT_SPOT
          ? spotFalloff(dot(-toLight, light.directionCosOuter.xyz), light.intensityCosInner.w,
                        light.directionCosOuter.w)
          : 1.0;
      e = light.intensityCosInner.rgb * falloff / r2;
      view = viewOfFace(light, cubeFace(-d));
      // A texel of a 90-degree face spans about 2 r / N metres at distance r.
      texelWorld = 2.0 * sqrt(r2) / float(shadowResolution);
    }
    float cosTheta = dot(n, toLight);
    if (cosTheta <= 0.0 || view < 0 || all(equal(e, vec3(0.0)))) continue;
    irradiance += e * cosTheta * visibility(view, p + n * normalOffsetTexels * texelWorld);
  }
  vec3 emission = texelFetch(gEmission, pixel, 0).rgb;
  imageStore(outDirect, pixel, vec4(emission + albedo / PI * irradiance, 1.0));
}
