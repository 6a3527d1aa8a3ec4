#version 450
// The subsurface LPV's light at every camera pixel that sees a translucent surface (thesis 5.4,
// step 4): the light leaving that surface (subsurface_exit.glsl) ADDED to the indirect image.
// Pixels of other surfaces, and uncovered ones, are left exactly as they are.
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

#include "../common/grid.glsl"
float subsurfaceGridValue(int channel, int k, int cell, int cells) {
  return grid[coefficientIndex(channel, k, SH_COEFFICIENTS, cell, cells)];
}
#include "subsurface_exit.glsl"

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(indirect)))) return;
  if (texelFetch(translucentMask, pixel, 0).r < 0.5) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) return;
  vec3 n = texelFetch(gNormal, pixel, 0).xyz;  // faces the camera: outward on a closed object
  vec3 radiance = subsurfaceExitingRadiance(position.xyz, n, gridOrigin, cellSize, resolution);
  imageStore(indirect, pixel, imageLoad(indirect, pixel) + vec4(radiance, 0.0));
}
