// Sky light injected column by column (injection "sky_columns", thesis 5.3 and 6.9.4), shared by
// the kernel shaders/injection/sky_columns.comp, the CPU kernel
// (variants/injection/sky_columns_cpu.cpp) and the double-precision C++ of the tests.
//
// A top-down orthographic depth map covers the grid's xz extent; its near plane is the grid's top
// face, its far plane the bottom face, so a texel's depth d in [0, 1] is the first surface below
// the grid's top along that vertical line, at height y = top - d * height (d = 1: none).
//
// Each texel is a vertical prism of cross-section a (m^2) open to the sky above its first
// surface. A constant sky of radiance L over the upper hemisphere gives irradiance pi L on a
// horizontal face, so the prism's open top lets in the flux pi L a (per channel). That flux is
// injected as a Lambertian emitter facing down, the same form a propagation face re-emits
// (shaders/propagation/standard_faces.glsl):
//     I(w) = pi L a / pi * max(0, -y . w) = L a max(0, -y . w)        [W/sr]
// whose integral over the sphere is pi L a: the injected flux is exactly the flux through the
// prism's top. It goes into the cell `shift` cells above the first surface (the lowest free cell
// for shift = 1), clamped to the grid's top layer.
// The thesis's own implementation (6.9.4) instead puts that VPL into every cell of the column from
// there up to the grid's top ("every free cell"): the column then holds the flux once per free
// cell, a sum that grows with the grid's resolution and the room above the surface, and that no
// normalisation in the thesis divides out. Kept to measure it beside the normalised form.
#ifndef LPVLAB_SKY_COLUMNS_GLSL
#define LPVLAB_SKY_COLUMNS_GLSL
#include "../common/sh.glsl"
#include "../common/grid.glsl"

// Height (world y) of the first surface below the grid's top at depth-map depth `depth`.
real skySurfaceHeight(real depth, real gridTop, real gridHeight) {
  return gridTop - depth * gridHeight;
}

// The layer (grid y index) that receives the light falling on a surface at height `surfaceY`
// (binned as grid.glsl's surfaceCell bins a surface facing up: one on a layer boundary goes to
// the layer above).
int skyInjectionLayer(real surfaceY, real shiftCells, real gridOriginY, real cellSize, int layers) {
  int layer = int(floor((surfaceY - gridOriginY) / cellSize + shiftCells + CELL_BOUNDARY_TOLERANCE));
  return clamp(layer, 0, layers - 1);
}

// The cell that depth-map texel `texel` (of a `size` map covering the grid's xz extent) lights,
// for the first surface at depth `depth` (< 1) below the grid's top: texel (i, j) is the column
// over x in [i, i+1) and z in [j, j+1) texel widths.
ivec3 skyColumnCell(ivec2 texel, ivec2 size, real depth, vec3 gridOrigin, real cellSize,
                    ivec3 resolution, real shiftCells) {
  real height = real(resolution.y) * cellSize;
  real surfaceY = skySurfaceHeight(depth, gridOrigin.y + height, height);
  return ivec3((texel.x * resolution.x) / size.x,
               skyInjectionLayer(surfaceY, shiftCells, gridOrigin.y, cellSize, resolution.y),
               (texel.y * resolution.z) / size.y);
}

// The highest layer a texel lights when its light goes into layer `layer`: that layer alone, or
// with `everyFreeCell` (the thesis's fill) every layer up to the grid's top.
int skyTopLayer(int layer, int layers, int everyFreeCell) {
  return everyFreeCell != 0 ? layers - 1 : layer;
}

// Coefficient k of I(w) = max(0, -y . w): the downward Lambertian lobe per unit of L a.
real skyDownwardLobeAt(int k) {
  return shCosineLobeAt(k, vec3(0.0, -1.0, 0.0));
}

#endif
