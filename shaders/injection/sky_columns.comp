#version 450
// Sky light into the light grid, one invocation per texel of the top-down depth map: the flux
// pi L a through the texel's open column top becomes a downward Lambertian lobe L a max(0, -y.w)
// in the cell `shiftCells` above the column's first surface (derivation and normalisation in
// sky_columns.glsl), or with everyFreeCell into every cell above it too (the thesis's fill). Texels
// that meet no surface inside the grid inject nothing: that light
// leaves through the grid's bottom without lighting anything.
#extension GL_EXT_shader_atomic_float : require
#include "sky_columns.glsl"

#include "sky_columns_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;

layout(binding = UNIT_SKY_DEPTH) uniform sampler2D skyDepth;
layout(std430, binding = BUFFER_GRID) buffer Grid { float grid[]; };

layout(location = LOCATION_GRID_ORIGIN) uniform vec3 gridOrigin;
layout(location = LOCATION_CELL_SIZE) uniform float cellSize;
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_SHIFT_CELLS) uniform float shiftCells;
layout(location = LOCATION_SKY_PER_TEXEL) uniform vec3 skyPerTexel;  // L a per channel, W/sr
layout(location = LOCATION_EVERY_FREE_CELL) uniform int everyFreeCell;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = textureSize(skyDepth, 0);
  if (texel.x >= size.x || texel.y >= size.y) return;
  float depth = texelFetch(skyDepth, texel, 0).r;
  if (depth >= 1.0) return;
  ivec3 cell = skyColumnCell(texel, size, depth, gridOrigin, cellSize, resolution, shiftCells);
  int cells = cellCount(resolution);
  int top = skyTopLayer(cell.y, resolution.y, everyFreeCell);
  for (int layer = cell.y; layer <= top; ++layer) {
    int index = cellIndex(ivec3(cell.x, layer, cell.z), resolution);
    for (int k = 0; k < SH_COEFFICIENTS; ++k) {
      float lobe = skyDownwardLobeAt(k);
      for (int channel = 0; channel < 3; ++channel)
        atomicAdd(grid[coefficientIndex(channel, k, SH_COEFFICIENTS, index, cells)],
                  skyPerTexel[channel] * lobe);
    }
  }
}
