// How far a cascade level is trusted at a point (thesis 5.1: a surface is shaded from the finest
// level that holds it, interpolated towards the next coarser one near that level's edge).
// Written in the shared GLSL/C++ subset (prelude.glsl): tests run it in double precision.
#ifndef LPVLAB_CASCADE_FADE_GLSL
#define LPVLAB_CASCADE_FADE_GLSL
#include "prelude.glsl"

// The fade of a level at grid coordinates g (of that level, resolution res): 0 outside the box
// shrunk by one cell (a trilinear read within a cell of the edge would clamp), rising linearly to 1
// over `blendCells` cells inward. blendCells = 0 gives a hard switch between levels.
real cascadeFade(vec3 g, ivec3 res, real blendCells) {
  real lowest = min(min(g.x, g.y), g.z);
  real highest = min(min(real(res.x) - g.x, real(res.y) - g.y), real(res.z) - g.z);
  real inside = min(lowest, highest) - real(1.0);
  if (blendCells <= real(0.0)) return inside >= real(0.0) ? real(1.0) : real(0.0);
  return clamp(inside / blendCells, real(0.0), real(1.0));
}

#endif
