// Grid geometry and addressing, shared by every kernel and by C++.
//
// A grid is an axis-aligned box: `origin` (world, metres) is the corner of cell (0,0,0), cells
// are cubes of edge `cellSize` (metres), `res` cells along each axis. Grid coordinates g are in
// cell units, g = (p - origin) / cellSize: cell c spans [c, c+1) and its centre is c + 0.5.
//
// Memory layout of a grid of SH coefficients (one float array): structure of arrays,
// index = (channel * coefficientCount + coefficient) * cellCount + cellIndex(c), so that a
// kernel reading one coefficient of neighbouring cells reads neighbouring memory.
#ifndef LPVLAB_GRID_GLSL
#define LPVLAB_GRID_GLSL
#include "prelude.glsl"

vec3 gridFromWorld(vec3 p, vec3 origin, real cellSize) {
  return (p - origin) / cellSize;
}

vec3 worldFromGrid(vec3 g, vec3 origin, real cellSize) {
  return origin + g * cellSize;
}

ivec3 cellContaining(vec3 g) {
  return ivec3(floor(g));
}

// Binning a point on a surface into cells (VPLs, GV surfels, sky layers): a point this close to a
// cell boundary (in cells) goes to the cell the surface's normal points into. Surfaces often lie
// exactly on a boundary (a grid fitted to the scene puts its walls on one; a VPL shifted by a
// whole number of cells lands on one), where float (GL) and double (CPU) arithmetic would
// otherwise round to different cells; the normal's side is also where the surface's light is.
const real CELL_BOUNDARY_TOLERANCE = 1e-4;

// The cell a surface point at grid coordinates g, with unit normal n, is binned into.
ivec3 surfaceCell(vec3 g, vec3 n) {
  return cellContaining(g + n * CELL_BOUNDARY_TOLERANCE);
}

bool cellInside(ivec3 c, ivec3 res) {
  return c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < res.x && c.y < res.y && c.z < res.z;
}

int cellIndex(ivec3 c, ivec3 res) {
  return c.x + res.x * (c.y + res.y * c.z);
}

int cellCount(ivec3 res) {
  return res.x * res.y * res.z;
}

int coefficientIndex(int channel, int coefficient, int coefficientCount, int cell, int cells) {
  return (channel * coefficientCount + coefficient) * cells + cell;
}

#endif
