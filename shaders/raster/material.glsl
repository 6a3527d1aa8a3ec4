// Scene materials for the raster passes (mirrors framework/pipeline/scene_gpu.h).
#ifndef LPVLAB_MATERIAL_GLSL
#define LPVLAB_MATERIAL_GLSL

struct GpuMaterial {
  vec4 baseColorCutoff;   // rgb: linear base colour factor; a: alpha cutoff (< 0: opaque)
  vec4 emissionTextured;  // rgb: emitted radiance W/(m^2 sr); a: 1 if a base colour texture is bound
};

#include "material_interface.glsl"
layout(std430, binding = BUFFER_MATERIALS) readonly buffer Materials { GpuMaterial materials[]; };
layout(binding = UNIT_BASE_COLOR_TEXTURE) uniform sampler2D baseColorTexture;  // sRGB texture: sampling linearises
layout(location = LOCATION_MATERIAL_INDEX) uniform int materialIndex;

// The linear albedo at uv; discards the fragment where an alpha mask cuts the surface out.
vec3 materialAlbedo(vec2 uv) {
  GpuMaterial m = materials[materialIndex];
  vec4 texel = m.emissionTextured.a > 0.5 ? texture(baseColorTexture, uv) : vec4(1.0);
  if (m.baseColorCutoff.a >= 0.0 && texel.a < m.baseColorCutoff.a) discard;
  return m.baseColorCutoff.rgb * texel.rgb;
}

vec3 materialEmission() { return materials[materialIndex].emissionTextured.rgb; }

#endif
