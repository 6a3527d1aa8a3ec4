#version 450
// The subsurface LPV's light at every camera pixel that sees a translucent surface (thesis 5.4,
// step 4): the accumulated SSLPV, trilinearly interpolated between the 8 nearest cell centres
// (clamped at the grid's edge) at the surface point, projected on the light leaving through the
// surface, L_o = <I, cosLobe(n)> / (pi s^2) (subsurface.glsl), ADDED to the indirect image.
// Pixels of other surfaces, and uncovered ones, are left exactly as they are.
#include "../common/sh.glsl"
#include "../common/grid.glsl"
#include "../rendering/trilinear_weights.glsl"
#include "subsurface.glsl"

#include "render_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;

layout(binding = UNIT_G_POSITION) uniform sampler2D gPosition;
layout(binding = UNIT_G_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_TRANSLUCENT_MASK) uniform sampler2D translucentMask;
layout(std430, binding = BUFFER_ACCUMULATED) readonly buffer Accumulated { float grid[]; };
layout(binding = IMAGE_INDIRECT, rgba32f) uniform image2D indirect;

layout(location = LOCATION_GRID_ORIGIN) uniform vec3 gridOrigin;
layout(location = LOCATION_CELL_SIZE) uniform float cellSize;
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(indirect)))) return;
  if (texelFetch(translucentMask, pixel, 0).r < 0.5) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) return;
  vec3 n = texelFetch(gNormal, pixel, 0).xyz;  // faces the camera: outward on a closed object
  float lobe[SH_MAX_COEFFICIENTS];
  for (int k = 0; k < SH_COEFFICIENTS; ++k) lobe[k] = subsurfaceExitLobeAt(k, n);
  // Cell centres sit at integer + 0.5 in grid coordinates.
  vec3 centred = gridFromWorld(position.xyz, gridOrigin, cellSize) - 0.5;
  vec3 base = floor(centred);
  vec3 f = centred - base;
  int cells = cellCount(resolution);
  vec3 projected = vec3(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    int index = cellIndex(clamp(ivec3(base) + o, ivec3(0), resolution - 1), resolution);
    for (int channel = 0; channel < 3; ++channel) {
      float v = 0.0;
      for (int k = 0; k < SH_COEFFICIENTS; ++k)
        v += grid[coefficientIndex(channel, k, SH_COEFFICIENTS, index, cells)] * lobe[k];
      projected[channel] += trilinearWeight(o, f) * v;
    }
  }
  vec3 radiance = vec3(subsurfaceExitRadiance(projected.r, cellSize),
                       subsurfaceExitRadiance(projected.g, cellSize),
                       subsurfaceExitRadiance(projected.b, cellSize));
  imageStore(indirect, pixel, imageLoad(indirect, pixel) + vec4(radiance, 0.0));
}
