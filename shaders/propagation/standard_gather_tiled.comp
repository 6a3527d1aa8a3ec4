#version 450
// Standard propagation by gathering, laid out for GPUs ([propagation] gpu_kernel = "tiled"): the
// same transfer as standard_gather.comp (standard_transfer.glsl's face loop, called with the same
// arguments in the same order), so the same grid; only where the source values come from differs.
//
// standard_gather.comp runs one invocation per cell in 4x4x4 groups and reads each source cell
// from memory six times (once per neighbour that gathers from it), leaving the re-reads to the
// caches. Here a work group is a TILE_X x TILE_Y tile of one z-plane, long along x so that a warp
// reads whole rows of each coefficient plane (the grid is x-fastest, grid.glsl), and it walks
// TILED_Z_SPAN planes up the grid (2.5D blocking):
//   - each invocation keeps its own column's cells below, at and above the current plane in
//     registers: the +-z neighbours, each read from memory once per walk;
//   - the current plane's tile, with a one-cell halo in x and y, is staged in shared memory: the
//     +-x and +-y neighbours come from there, and only the halo is read again by the next tile.
// Source reads per cell-iteration: 1 + 2 (TILE_X + TILE_Y) / (TILE_X TILE_Y) + 1 / TILED_Z_SPAN
// cells instead of 6 (standard_work.h). The GV corners are read as in the simple kernel.
// Invocations past the grid's edge stay to the end (they take part in the barriers) and write
// nothing. The tile sizes are specialisation constants, chosen per SH order by
// variants/propagation/standard.cpp so that the shared tile fits GL's guaranteed 32 KiB.
// Not done: several iterations per dispatch (temporal blocking), which the halo would allow.
#include "standard_interface.glsl"
layout(local_size_x_id = SPEC_TILE_X, local_size_y_id = SPEC_TILE_Y,
       local_size_z = TILED_GROUP_SIZE_Z) in;
layout(constant_id = 0) const float FAR_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float SIDE_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 2) const int SH_COEFFICIENTS = 4;
layout(constant_id = 3) const bool HAS_GV = false;
layout(constant_id = 4) const bool BOUNCES = false;  // re-emit blocked light (only with HAS_GV)

layout(std430, binding = BUFFER_SOURCE) readonly buffer Source { float source[]; };
layout(std430, binding = BUFFER_TARGET) writeonly buffer Target { float target[]; };
layout(std430, binding = BUFFER_ACCUMULATED) buffer Accumulated { float accumulated[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME) readonly buffer GeometryVolume { float gvBlocking[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME_ALBEDO) readonly buffer GeometryVolumeAlbedo { vec4 gvAlbedo[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_ITERATION) uniform int iteration;
layout(location = LOCATION_FIRST_OCCLUDED_ITERATION) uniform int firstOccludedIteration;

const int N = SH_COEFFICIENTS;  // arrays sized by the specialisation constant stay in registers
#include "standard_transfer.glsl"

const int TILE_X = int(gl_WorkGroupSize.x);
const int TILE_Y = int(gl_WorkGroupSize.y);
const int PLANE_X = TILE_X + 2;  // the tile and its halo
const int CELL_FLOATS = 3 * N;
shared float plane[PLANE_X * (TILE_Y + 2) * CELL_FLOATS];

float below[3 * N];   // this invocation's column: the cell under the current plane
float centre[3 * N];  // the cell in it
float above[3 * N];   // the cell over it

// The slot in `plane` of the tile position t (-1 .. TILE inclusive: the halo).
int planeSlot(ivec2 t) {
  return ((t.y + 1) * PLANE_X + t.x + 1) * CELL_FLOATS;
}

// Copies the source cell c (inside the grid) into `plane` at tile position t.
void stageFromSource(ivec3 c, ivec2 t, int cells) {
  loadSourceCell(cellIndex(c, resolution), cells);
  int slot = planeSlot(t);
  for (int i = 0; i < CELL_FLOATS; ++i) plane[slot + i] = sourceCell[i];
}

void main() {
  ivec2 t = ivec2(gl_LocalInvocationID.xy);
  ivec3 first = ivec3(ivec2(gl_WorkGroupID.xy) * ivec2(TILE_X, TILE_Y) + t,
                      int(gl_WorkGroupID.z) * TILED_Z_SPAN);
  int end = min(first.z + TILED_Z_SPAN, resolution.z);
  bool inColumn = first.x < resolution.x && first.y < resolution.y;
  int cells = cellCount(resolution);
  bool occluded = iteration >= firstOccludedIteration;
  for (int i = 0; i < CELL_FLOATS; ++i) below[i] = centre[i] = 0.0;
  if (inColumn && first.z > 0) {
    loadSourceCell(cellIndex(first - ivec3(0, 0, 1), resolution), cells);
    for (int i = 0; i < CELL_FLOATS; ++i) below[i] = sourceCell[i];
  }
  if (inColumn && first.z < end) {
    loadSourceCell(cellIndex(first, resolution), cells);
    for (int i = 0; i < CELL_FLOATS; ++i) centre[i] = sourceCell[i];
  }
  for (int z = first.z; z < end; ++z) {
    ivec3 cell = ivec3(first.xy, z);
    for (int i = 0; i < CELL_FLOATS; ++i) above[i] = 0.0;
    if (inColumn && z + 1 < resolution.z) {
      loadSourceCell(cellIndex(cell + ivec3(0, 0, 1), resolution), cells);
      for (int i = 0; i < CELL_FLOATS; ++i) above[i] = sourceCell[i];
    }
    barrier();  // every invocation has finished reading the previous plane
    if (inColumn) {
      int slot = planeSlot(t);
      for (int i = 0; i < CELL_FLOATS; ++i) plane[slot + i] = centre[i];
      // The halo: the tile's edge invocations stage the cells beyond it that lie in the grid.
      if (t.x == 0 && cell.x > 0) stageFromSource(cell - ivec3(1, 0, 0), t - ivec2(1, 0), cells);
      if (t.x == TILE_X - 1 && cell.x + 1 < resolution.x)
        stageFromSource(cell + ivec3(1, 0, 0), t + ivec2(1, 0), cells);
      if (t.y == 0 && cell.y > 0) stageFromSource(cell - ivec3(0, 1, 0), t - ivec2(0, 1), cells);
      if (t.y == TILE_Y - 1 && cell.y + 1 < resolution.y)
        stageFromSource(cell + ivec3(0, 1, 0), t + ivec2(0, 1), cells);
    }
    memoryBarrierShared();
    barrier();
    if (inColumn) {
      if (HAS_GV && occluded) loadGvCorners(cell, resolution + 1);
      float gathered[3 * N];
      for (int i = 0; i < CELL_FLOATS; ++i) gathered[i] = 0.0;
      // The neighbours in standard_gather.comp's order (-x, +x, -y, +y, -z, +z): the same sum.
      for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
          ivec3 offset = ivec3(0);
          offset[axis] = sign;
          ivec3 neighbour = cell + offset;
          if (!cellInside(neighbour, resolution)) continue;
          if (axis == 2) {
            for (int i = 0; i < CELL_FLOATS; ++i) sourceCell[i] = sign < 0 ? below[i] : above[i];
          } else {
            int slot = planeSlot(t + offset.xy);
            for (int i = 0; i < CELL_FLOATS; ++i) sourceCell[i] = plane[slot + i];
          }
          standardTransfer(neighbour, vec3(-offset), occluded, true, false, resolution,
                           FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
          for (int i = 0; i < CELL_FLOATS; ++i) gathered[i] += transferred[i];
        }
      }
      if (BOUNCES && occluded) {
        for (int i = 0; i < CELL_FLOATS; ++i) sourceCell[i] = centre[i];
        for (int axis = 0; axis < 3; ++axis) {
          for (int sign = -1; sign <= 1; sign += 2) {
            vec3 d = vec3(0.0);
            d[axis] = float(sign);
            standardTransfer(cell, d, occluded, false, true, resolution, FAR_FACE_SOLID_ANGLE,
                             SIDE_FACE_SOLID_ANGLE);
            for (int i = 0; i < CELL_FLOATS; ++i) gathered[i] += bounced[i];
          }
        }
      }
      int index = cellIndex(cell, resolution);
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < N; ++k) {
          int i = coefficientIndex(channel, k, N, index, cells);
          target[i] = gathered[channel * N + k];
          accumulated[i] += gathered[channel * N + k];
        }
    }
    for (int i = 0; i < CELL_FLOATS; ++i) {
      below[i] = centre[i];
      centre[i] = above[i];
    }
  }
}
