#version 450
// The camera's G-buffer. Surfaces are two-sided: the normal is turned to face the camera.
#include "material.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 texcoord;

#include "gbuffer_interface.glsl"
layout(location = LOCATION_CAMERA_POSITION) uniform vec3 cameraPosition;
layout(location = LOCATION_CAMERA_FORWARD) uniform vec3 cameraForward;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outAlbedo;
layout(location = 3) out vec4 outEmission;

void main() {
  vec3 albedo = materialAlbedo(texcoord);
  vec3 n = normalize(worldNormal);
  if (dot(n, cameraPosition - worldPosition) < 0.0) n = -n;
  outPosition = vec4(worldPosition, 1.0);
  outNormal = vec4(n, dot(worldPosition - cameraPosition, cameraForward));
  outAlbedo = vec4(albedo, 1.0);
  outEmission = vec4(materialEmission(), 1.0);
}
