// What the camera's G-buffer stores of a surface point, for every program that draws into it
// (raster/gbuffer.frag for the scene's meshes, particles/billboard_gbuffer.frag for light-field
// particles): gbuffer_texel.glsl's texel, the albedo and the emission.
#ifndef LPVLAB_GBUFFER_OUTPUT_GLSL
#define LPVLAB_GBUFFER_OUTPUT_GLSL

#include "gbuffer_interface.glsl"
#include "gbuffer_texel.glsl"
layout(location = LOCATION_CAMERA_POSITION) uniform vec3 cameraPosition;
layout(location = LOCATION_CAMERA_FORWARD) uniform vec3 cameraForward;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outAlbedo;
layout(location = 3) out vec4 outEmission;

void writeGBuffer(vec3 worldPosition, vec3 worldNormal, vec3 albedo, vec3 emission) {
  GBufferTexel texel = gbufferTexel(worldPosition, worldNormal, cameraPosition, cameraForward);
  outPosition = texel.position;
  outNormal = texel.normal;
  outAlbedo = vec4(albedo, 1.0);
  outEmission = vec4(emission, 1.0);
}

#endif
