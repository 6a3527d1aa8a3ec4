#version 450
// Reflective shadow map of one light view. Each texel stores the surface it sees and the flux
// that surface patch reflects: albedo times the flux arriving at it (rsm_texel.glsl).
#include "material.glsl"
#include "rsm_texel.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 texcoord;

#include "rsm_interface.glsl"
#include "../common/light_records_interface.glsl"
layout(std430, binding = BUFFER_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = BUFFER_VIEWS) readonly buffer Views { GpuView views[]; };
layout(location = LOCATION_VIEW_INDEX) uniform int viewIndex;
layout(location = LOCATION_RESOLUTION) uniform int resolution;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outFlux;

void main() {
  vec3 albedo = materialAlbedo(texcoord);
  GpuView view = views[viewIndex];
  RsmTexelLight arriving = rsmTexelLight(view, lights[int(view.params.z)], worldPosition,
                                         worldNormal, gl_FragCoord.xy, resolution);
  outPosition = vec4(worldPosition, 1.0);
  outNormal = vec4(arriving.normal, 0.0);
  outFlux = vec4(albedo * arriving.flux, 1.0);
}
