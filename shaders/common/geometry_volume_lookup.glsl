// Kernel-side GV lookup: the blocking potential trilinearly interpolated at a point, from a GV
// buffer the including kernel declares as
//   layout(std430, binding = ...) readonly buffer GeometryVolume { float gvBlocking[]; };
// with the GV's resolution (the light grid's + 1) in `gvResolution`. Outside the GV nothing
// blocks. Layout: coefficient k of GV cell i at gvBlocking[k * cellCount + i].
// Written in the shared subset too: a C++ test that defines `gvBlocking` (any indexable array)
// and `using glm::mix` before including it runs the same lookup in double precision.
#ifndef LPVLAB_GEOMETRY_VOLUME_LOOKUP_GLSL
#define LPVLAB_GEOMETRY_VOLUME_LOOKUP_GLSL
#include "geometry_volume.glsl"
#include "grid.glsl"

vec4 gvCell(ivec3 c, ivec3 gvResolution) {
  if (!cellInside(c, gvResolution)) return vec4(0.0);
  int cells = cellCount(gvResolution);
  int i = cellIndex(c, gvResolution);
  return vec4(gvBlocking[i], gvBlocking[cells + i], gvBlocking[2 * cells + i], gvBlocking[3 * cells + i]);
}

// Blocking potential at light-grid coordinates g (GV cell centres at integer g).
vec4 gvBlockingAt(vec3 g, ivec3 gvResolution) {
  vec3 p = gvFromLightGrid(g) - 0.5;
  vec3 base = floor(p);
  vec3 f = p - base;
  vec4 sum = vec4(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    real w = w3.x * w3.y * w3.z;
    if (w > 0.0) sum += w * gvCell(ivec3(base) + o, gvResolution);
  }
  return sum;
}

#endif
