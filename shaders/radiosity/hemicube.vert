#version 450
// The hemicube's item buffer (seed 004, 3.6-3.7): every patch drawn with its index, seen from one
// patch's centroid through one face of its hemicube.
#include "hemicube_interface.glsl"
layout(location = HEMICUBE_ATTRIBUTE_POSITION) in vec3 position;
layout(location = HEMICUBE_ATTRIBUTE_PATCH) in uint patchIndex;

layout(location = HEMICUBE_LOCATION_CLIP_FROM_WORLD) uniform mat4 clipFromWorld;

layout(location = 0) flat out uint patchOut;

void main() {
  patchOut = patchIndex;
  gl_Position = clipFromWorld * vec4(position, 1.0);
}
