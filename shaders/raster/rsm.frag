#version 450
// Reflective shadow map of one light view, the scene's meshes (rsm_output.glsl).
#include "material.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 texcoord;
layout(location = 3) in vec3 vertexColor;

#include "rsm_output.glsl"

void main() {
  writeRsm(worldPosition, worldNormal, materialAlbedo(texcoord) * vertexColor);
}
