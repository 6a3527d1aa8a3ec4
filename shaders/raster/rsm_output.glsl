// What one light view's reflective shadow map stores of a surface point, for every program that
// draws into it (raster/rsm.frag for the scene's meshes, particles/billboard_rsm.frag for
// light-field particles): the surface and the flux it reflects, albedo times the flux arriving
// at the texel's patch (rsm_texel.glsl).
#ifndef LPVLAB_RSM_OUTPUT_GLSL
#define LPVLAB_RSM_OUTPUT_GLSL

#include "rsm_texel.glsl"
#include "rsm_interface.glsl"
#include "../common/light_records_interface.glsl"
layout(std430, binding = BUFFER_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = BUFFER_VIEWS) readonly buffer Views { GpuView views[]; };
layout(location = LOCATION_VIEW_INDEX) uniform int viewIndex;
layout(location = LOCATION_RESOLUTION) uniform int resolution;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outFlux;

void writeRsm(vec3 worldPosition, vec3 worldNormal, vec3 albedo) {
  GpuView view = views[viewIndex];
  RsmTexelLight arriving = rsmTexelLight(view, lights[int(view.params.z)], worldPosition,
                                         worldNormal, gl_FragCoord.xy, resolution);
  outPosition = vec4(worldPosition, 1.0);
  outNormal = vec4(arriving.normal, 0.0);
  outFlux = vec4(albedo * arriving.flux, 1.0);
}

#endif
