#version 450
// Indirect light at every G-buffer pixel from the accumulated light grid, trilinearly
// interpolated between the 8 nearest cell centres (clamped at the grid's edge), at any SH order.
// The grid holds intensity I (W/sr) per cell; spread over the cell's cross-section it is the
// radiance L = I / cellSize^2 (Kaplanyan and Dachsbacher 2010). The irradiance from the light
// arriving at a surface with normal n is E = integral L(w) max(0, -n . w) dw = <L, cosLobe(-n)>,
// and the Lambertian surface reflects L_o = albedo / pi * E.
#include "../common/sh.glsl"
#include "../common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;

layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 1) uniform sampler2D gNormal;
layout(binding = 2) uniform sampler2D gAlbedo;
layout(std430, binding = 0) readonly buffer Accumulated { float grid[]; };
layout(binding = 0, rgba32f) uniform writeonly image2D outIndirect;

layout(location = 0) uniform vec3 gridOrigin;
layout(location = 1) uniform float cellSize;
layout(location = 2) uniform ivec3 resolution;
layout(location = 3) uniform float normalOffsetCells;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(outIndirect)))) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) {
    imageStore(outIndirect, pixel, vec4(0.0));
    return;
  }
  vec3 n = texelFetch(gNormal, pixel, 0).xyz;
  vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
  vec3 p = position.xyz + n * (normalOffsetCells * cellSize);
  // Cell centres sit at integer + 0.5 in grid coordinates.
  vec3 g = gridFromWorld(p, gridOrigin, cellSize) - 0.5;
  vec3 base = floor(g);
  vec3 f = g - base;
  int cells = cellCount(resolution);
  float lobe[SH_MAX_COEFFICIENTS];
  for (int k = 0; k < SH_COEFFICIENTS; ++k) lobe[k] = shCosineLobeAt(k, -n);
  vec3 e = vec3(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    ivec3 c = clamp(ivec3(base) + o, ivec3(0), resolution - 1);
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    float w = w3.x * w3.y * w3.z;
    int index = cellIndex(c, resolution);
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < SH_COEFFICIENTS; ++k)
        e[channel] += w * grid[coefficientIndex(channel, k, SH_COEFFICIENTS, index, cells)] * lobe[k];
  }
  vec3 radiance = albedo / PI * max(e, vec3(0.0)) / (cellSize * cellSize);
  imageStore(outIndirect, pixel, vec4(radiance, 1.0));
}
