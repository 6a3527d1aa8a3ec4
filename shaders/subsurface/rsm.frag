#version 450
// The subsurface LPV's reflective shadow map of one light view (thesis 5.4, step 1). Translucent
// surfaces store the flux they let into their object, transmittance times the flux arriving at
// the texel's patch (raster/rsm_texel.glsl), and the INWARD normal: the direction of the VPL
// that carries that flux into the object (step 2), so the RSM injection kernel
// (injection/rsm_vpl.comp, shift 0) injects it unchanged. Every other surface is drawn as an
// occluder only (w = 0, no flux): it injects nothing, and shades translucent surfaces behind it.
#include "translucency.glsl"
#include "../raster/rsm_texel.glsl"

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
  materialAlbedo(texcoord);  // alpha-masked texels are cut out here too
  if (!materialTranslucent()) {
    outPosition = vec4(0.0);
    outNormal = vec4(0.0);
    outFlux = vec4(0.0);
    return;
  }
  GpuView view = views[viewIndex];
  RsmTexelLight arriving = rsmTexelLight(view, lights[int(view.params.z)], worldPosition,
                                         worldNormal, gl_FragCoord.xy, resolution);
  outPosition = vec4(worldPosition, 1.0);
  outNormal = vec4(-arriving.normal, 0.0);
  outFlux = vec4(materialTransmittance() * arriving.flux, 1.0);
}
