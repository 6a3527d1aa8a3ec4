// The scene materials' translucency for the subsurface LPV's raster passes, one record per
// material (indexed like material.glsl's, by materialIndex), uploaded by
// variants/rendering/subsurface.cpp: rgb: transmittance (0: opaque), a: extinction (1/m).
#ifndef LPVLAB_TRANSLUCENCY_GLSL
#define LPVLAB_TRANSLUCENCY_GLSL
#include "../raster/material.glsl"

#include "translucency_interface.glsl"
layout(std430, binding = BUFFER_TRANSLUCENCY) readonly buffer Translucency { vec4 translucency[]; };

vec3 materialTransmittance() { return translucency[materialIndex].rgb; }

bool materialTranslucent() {
  vec3 t = materialTransmittance();
  return t.r + t.g + t.b > 0.0;
}

#endif
