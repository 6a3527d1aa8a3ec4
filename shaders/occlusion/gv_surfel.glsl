// Adding one surfel to a geometry volume (thesis 4.3, eq. 4.4; the convention is in
// shaders/common/geometry_volume.glsl): a surfel of area A whose normal n faces its viewer adds
// A / s^2 * cosLobe(-n) to the GV cell containing it, without any shift, atomically.
// It declares the target GV buffer (binding 0) and the uniforms at locations 0..2 below; the
// including kernel enables GL_EXT_shader_atomic_float.
#ifndef LPVLAB_GV_SURFEL_GLSL
#define LPVLAB_GV_SURFEL_GLSL
#include "../common/sh.glsl"
#include "../common/grid.glsl"

layout(std430, binding = 0) buffer Target { float gv[]; };  // the GV's blocking coefficients
layout(location = 0) uniform vec3 gvOrigin;      // corner of GV cell (0,0,0), metres
layout(location = 1) uniform float cellSize;     // s, metres (the light grid's)
layout(location = 2) uniform ivec3 gvResolution;

void gvAddSurfel(vec3 p, vec3 n, float area) {
  ivec3 cell = cellContaining(gridFromWorld(p, gvOrigin, cellSize));
  if (!cellInside(cell, gvResolution)) return;
  int cells = cellCount(gvResolution);
  int index = cellIndex(cell, gvResolution);
  float scale = area / (cellSize * cellSize);
  for (int k = 0; k < 4; ++k) atomicAdd(gv[k * cells + index], scale * shCosineLobeAt(k, -n));
}

#endif
