// What the camera's G-buffer stores of a surface point, for every program that draws into it
// (raster/gbuffer.frag for the scene's meshes, particles/billboard_gbuffer.frag for light-field
// particles). Surfaces are two-sided: the normal is turned to face the camera.
#ifndef LPVLAB_GBUFFER_OUTPUT_GLSL
#define LPVLAB_GBUFFER_OUTPUT_GLSL

#include "gbuffer_interface.glsl"
layout(location = LOCATION_CAMERA_POSITION) uniform vec3 cameraPosition;
layout(location = LOCATION_CAMERA_FORWARD) uniform vec3 cameraForward;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outAlbedo;
layout(location = 3) out vec4 outEmission;

void writeGBuffer(vec3 worldPosition, vec3 worldNormal, vec3 albedo, vec3 emission) {
  vec3 n = normalize(worldNormal);
  if (dot(n, cameraPosition - worldPosition) < 0.0) n = -n;
  outPosition = vec4(worldPosition, 1.0);
  outNormal = vec4(n, dot(worldPosition - cameraPosition, cameraForward));
  outAlbedo = vec4(albedo, 1.0);
  outEmission = vec4(emission, 1.0);
}

#endif
