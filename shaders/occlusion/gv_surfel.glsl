// Adding one surfel to a geometry volume (thesis 4.3, eq. 4.4; the convention is in
// shaders/common/geometry_volume.glsl): a surfel of area A whose normal n faces its viewer adds
// A / s^2 * cosLobe(-n) to the GV cell containing it, without any shift, atomically, times
// blockingScale (the occlusion strategy's `blocking_scale`, 1 by default: a constant to fit; a
// uniform, not a specialisation constant: at 0 the compiler would drop the kernel's uniforms).
// With WITH_ALBEDO it also adds the surfel's albedo rho, weighted by its blocking weight A / s^2,
// to the GV's albedo (rho A / s^2, A / s^2), so that a cell's mean albedo is the surfels' area-
// weighted mean (variants/resources/geometry_volume.h).
// It declares the target GV buffers and the uniforms of gv_surfel_interface.glsl, and the
// specialisation constant 0 below; the including kernel enables GL_EXT_shader_atomic_float.
#ifndef LPVLAB_GV_SURFEL_GLSL
#define LPVLAB_GV_SURFEL_GLSL
#include "../common/sh.glsl"
#include "../common/grid.glsl"
#include "../common/geometry_volume.glsl"

#include "gv_surfel_interface.glsl"
layout(std430, binding = BUFFER_TARGET) buffer Target { float gv[]; };  // the GV's blocking coefficients
layout(location = LOCATION_GV_ORIGIN) uniform vec3 gvOrigin;      // corner of GV cell (0,0,0), metres
layout(location = LOCATION_CELL_SIZE) uniform float cellSize;     // s, metres (the light grid's)
layout(location = LOCATION_GV_RESOLUTION) uniform ivec3 gvResolution;
layout(location = LOCATION_BLOCKING_SCALE) uniform float blockingScale;
layout(constant_id = 0) const bool WITH_ALBEDO = false;
layout(std430, binding = BUFFER_ALBEDO) buffer Albedo { float gvAlbedo[]; };  // 4 floats per GV cell

// `albedoKnown`: rho is the surfel's albedo; otherwise only its blocking is added.
void gvAddSurfel(vec3 p, vec3 n, float area, vec3 rho, bool albedoKnown) {
  ivec3 cell = surfaceCell(gridFromWorld(p, gvOrigin, cellSize), n);
  if (!cellInside(cell, gvResolution)) return;
  int cells = cellCount(gvResolution);
  int index = cellIndex(cell, gvResolution);
  // The albedo's weight is the unscaled blocking: the mean albedo does not depend on the scale.
  float weight = gvSurfelWeight(area, cellSize);
  vec4 blocking = gvSurfelBlocking(n, weight, blockingScale);
  for (int k = 0; k < 4; ++k) atomicAdd(gv[k * cells + index], blocking[k]);
  if (WITH_ALBEDO && albedoKnown) {
    for (int c = 0; c < 3; ++c) atomicAdd(gvAlbedo[4 * index + c], weight * rho[c]);
    atomicAdd(gvAlbedo[4 * index + 3], weight);
  }
}

#endif
