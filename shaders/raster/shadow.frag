#version 450
// Depth-only pass of a shadow map; alpha-masked surfaces cut out their shadows too.
#include "material.glsl"

layout(location = 2) in vec2 texcoord;

void main() {
  materialAlbedo(texcoord);
}
