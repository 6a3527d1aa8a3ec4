#version 450
// The camera's G-buffer of the scene's meshes (gbuffer_output.glsl).
#include "material.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 texcoord;
layout(location = 3) in vec3 vertexColor;

#include "gbuffer_output.glsl"

void main() {
  writeGBuffer(worldPosition, worldNormal, materialAlbedo(texcoord) * vertexColor, materialEmission());
}
