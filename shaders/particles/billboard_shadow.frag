#version 450
// Light-field particles into a shadow map: the depth of the model's surface seen from the light
// (the billboard faces the light, so the shadow is the model's silhouette from there).
#include "light_field_sample.glsl"

void main() {
  lightFieldSurface();
}
