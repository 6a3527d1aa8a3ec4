#version 450
// One view of a particle model's light field (framework/particles/light_field.h), drawn with
// raster/scene.vert in the model's object space under an orthographic view along -viewDirection:
// the albedo with coverage (1 where the model is, the target's clear 0 elsewhere), and the
// object-space normal turned towards the viewer with the surface's offset along viewDirection
// from the plane through the model's centre (positive towards the viewer), which a billboard
// adds back to put each fragment where the model's surface is. Both are premultiplied by the
// coverage (here 1), so that averaging them into mipmaps weighs covered texels alone and a
// reader divides by the averaged coverage.
#include "../raster/material.glsl"

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;
layout(location = 2) in vec2 texcoord;
layout(location = 3) in vec3 vertexColor;

#include "capture_interface.glsl"
layout(location = LOCATION_VIEW_DIRECTION) uniform vec3 viewDirection;

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormalOffset;

void main() {
  vec3 albedo = materialAlbedo(texcoord) * vertexColor;
  vec3 n = normalize(objectNormal);
  if (dot(n, viewDirection) < 0.0) n = -n;  // two-sided, as every lpvlab surface
  outAlbedo = vec4(albedo, 1.0);
  outNormalOffset = vec4(n, dot(objectPosition, viewDirection));
}
