#version 450
// Light-field particles into the camera's G-buffer (gbuffer_output.glsl), lit afterwards like
// every other surface: direct light with shadows, the grid's indirect light.
#include "light_field_sample.glsl"
#include "../raster/gbuffer_output.glsl"

void main() {
  LightFieldSurface s = lightFieldSurface();
  writeGBuffer(s.worldPosition, s.worldNormal, s.albedo, vec3(0.0));
}
