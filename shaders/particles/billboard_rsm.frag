#version 450
// Light-field particles into a light view's reflective shadow map (rsm_output.glsl): the flux
// they reflect is injected into the grid like any surface's.
#include "light_field_sample.glsl"
#include "../raster/rsm_output.glsl"

void main() {
  LightFieldSurface s = lightFieldSurface();
  writeRsm(s.worldPosition, s.worldNormal, s.albedo);
}
