#version 450
// Geometry-volume injection from the reflective shadow maps: every covered RSM texel is a surfel
// whose area is its footprint on the surface, with (WITH_ALBEDO) the albedo its reflected flux
// tells (gv_surfel_sources.glsl); a texel whose albedo is unknown adds blocking only.
#extension GL_EXT_shader_atomic_float : require
#include "gv_surfel.glsl"
#include "gv_surfel_sources.glsl"

#include "gv_rsm_interface.glsl"
#include "../common/light_records_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(binding = UNIT_SURFEL_POSITION) uniform sampler2DArray rsmPosition;
layout(binding = UNIT_SURFEL_NORMAL) uniform sampler2DArray rsmNormal;
layout(binding = UNIT_SURFEL_ALBEDO) uniform sampler2DArray rsmFlux;
layout(std430, binding = BUFFER_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = BUFFER_VIEWS) readonly buffer Views { GpuView views[]; };
layout(location = LOCATION_RSM_RESOLUTION) uniform int rsmResolution;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (texel.x >= rsmResolution || texel.y >= rsmResolution) return;
  vec4 position = texelFetch(rsmPosition, texel, 0);
  if (position.w == 0.0) return;
  vec3 p = position.xyz;
  vec3 n = texelFetch(rsmNormal, texel, 0).xyz;
  GpuView view = views[texel.z];
  GpuLight light = lights[int(view.params.z)];
  float area = gvRsmSurfelArea(view, light, p, n, rsmResolution);
  GvSurfelAlbedo albedo = GvSurfelAlbedo(vec3(0.0), false);
  if (WITH_ALBEDO)
    albedo = gvRsmSurfelAlbedo(view, light, p, n, vec2(texel.xy) + 0.5,
                               texelFetch(rsmFlux, texel, 0).rgb, rsmResolution);
  gvAddSurfel(p, n, area, albedo.albedo, albedo.known);
}
