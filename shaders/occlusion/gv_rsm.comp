#version 450
// Geometry-volume injection from the reflective shadow maps: every covered RSM texel is a surfel
// whose area is its footprint on the surface (surfel_area.glsl), perspective for the cube faces
// of point and spot lights, orthographic for a directional light's box. With WITH_ALBEDO, the
// surfel's albedo is its reflected flux (the RSM) over the flux arriving at it
// (raster/rsm_texel.glsl, the very function the RSM multiplied by the albedo); a texel whose
// arriving light is 0 in some channel (outside a spot's cone, a light without that colour) tells
// nothing about the albedo and adds blocking only.
#extension GL_EXT_shader_atomic_float : require
#include "gv_surfel.glsl"
#include "surfel_area.glsl"
#include "../raster/rsm_texel.glsl"

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
  float area;
  if (view.params.x == 1.0) {
    area = orthographicSurfelArea(view.params.y / float(rsmResolution),
                                  dot(n, -light.directionCosOuter.xyz));
  } else {
    vec3 toLight = light.positionType.xyz - p;
    float distance = length(toLight);
    float depth = (view.clipFromWorld * vec4(p, 1.0)).w;  // distance along the face's axis
    area = perspectiveSurfelArea(2.0 * view.params.y / float(rsmResolution), depth, distance,
                                 dot(n, toLight) / distance);
  }
  vec3 albedo = vec3(0.0);
  bool albedoKnown = false;
  if (WITH_ALBEDO) {
    vec3 arriving = rsmTexelLight(view, light, p, n, vec2(texel.xy) + 0.5, rsmResolution).flux;
    albedoKnown = min(arriving.r, min(arriving.g, arriving.b)) > 0.0;
    if (albedoKnown) albedo = texelFetch(rsmFlux, texel, 0).rgb / arriving;
  }
  gvAddSurfel(p, n, area, albedo, albedoKnown);
}
