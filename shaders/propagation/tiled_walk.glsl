// The walk of a tiled gather (gpu_kernel = "tiled"; standard_gather_tiled.comp,
// directed_gather_tiled.comp): where a gathering cell's six neighbours' light comes from, laid out
// for GPUs, so that each kernel keeps its own transfer and only the reads differ from its simple
// layout.
//
// A work group is a TILE_X x TILE_Y tile of one z-plane, long along x so that a warp reads whole
// rows of each coefficient plane (the grid is x-fastest, grid.glsl), and it walks TILED_Z_SPAN
// planes up the grid (2.5D blocking):
//   - each invocation keeps its own column's cells below, at and above the current plane in
//     registers: the -z and +z neighbours, each read from memory once per walk;
//   - the current plane's tile, with a one-cell halo in x and y, is staged in shared memory: the
//     -x, +x, -y and +y neighbours come from there, and only the halo is read again by the next
//     tile.
// Source reads per cell-iteration: 1 + 2 (TILE_X + TILE_Y) / (TILE_X TILE_Y) + 1 / TILED_Z_SPAN
// cells instead of 6 (variants/propagation/tiled_walk.h). Invocations past the grid's edge stay
// to the end (they take part in the barriers) and write nothing.
//
// The including kernel declares, before including this file:
//   layout(local_size_x_id = SPEC_TILE_X, local_size_y_id = SPEC_TILE_Y, ...) in;
//   const int N                            coefficients per channel (specialisation constant)
//   buffer ... { float source[]; }         the light of the previous iteration
//   uniform ivec3 resolution
// and runs:
//   TiledWalk walk = tiledWalkBegin();
//   for (int z = walk.first.z; z < walk.end; ++z) {
//     ivec3 cell = tiledWalkStage(walk, z);        // every invocation: it has barriers
//     if (walk.inColumn)
//       for each neighbour offset inside the grid: tiledWalkNeighbour(walk, offset) -> walkCell
//     tiledWalkAdvance();
//   }
// `walkCentre` holds the cell's own light meanwhile.
#ifndef LPVLAB_TILED_WALK_GLSL
#define LPVLAB_TILED_WALK_GLSL
#include "../common/grid.glsl"

const int TILE_X = int(gl_WorkGroupSize.x);
const int TILE_Y = int(gl_WorkGroupSize.y);
const int WALK_PLANE_X = TILE_X + 2;  // the tile and its halo
const int WALK_CELL_FLOATS = 3 * N;
shared float walkPlane[WALK_PLANE_X * (TILE_Y + 2) * WALK_CELL_FLOATS];

float walkBelow[3 * N];   // this invocation's column: the cell under the current plane
float walkCentre[3 * N];  // the cell in it
float walkAbove[3 * N];   // the cell over it
float walkCell[3 * N];    // a neighbour's light, after tiledWalkNeighbour

struct TiledWalk {
  ivec2 t;          // the invocation's place in the tile
  ivec3 first;      // its column's first cell
  int end;          // one past its last z
  bool inColumn;    // its column is inside the grid
  int cells;
};

// The slot in walkPlane of the tile position t (-1 .. TILE inclusive: the halo).
int walkSlot(ivec2 t) {
  return ((t.y + 1) * WALK_PLANE_X + t.x + 1) * WALK_CELL_FLOATS;
}

// The source cell c (inside the grid) into walkCell.
void walkLoad(ivec3 c, int cells) {
  int index = cellIndex(c, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < N; ++k)
      walkCell[channel * N + k] = source[coefficientIndex(channel, k, N, index, cells)];
}

// The source cell c (inside the grid) into walkPlane at tile position t.
void walkStageFromSource(ivec3 c, ivec2 t, int cells) {
  walkLoad(c, cells);
  int slot = walkSlot(t);
  for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkPlane[slot + i] = walkCell[i];
}

TiledWalk tiledWalkBegin() {
  TiledWalk walk;
  walk.t = ivec2(gl_LocalInvocationID.xy);
  walk.first = ivec3(ivec2(gl_WorkGroupID.xy) * ivec2(TILE_X, TILE_Y) + walk.t,
                     int(gl_WorkGroupID.z) * TILED_Z_SPAN);
  walk.end = min(walk.first.z + TILED_Z_SPAN, resolution.z);
  walk.inColumn = walk.first.x < resolution.x && walk.first.y < resolution.y;
  walk.cells = cellCount(resolution);
  for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkBelow[i] = walkCentre[i] = 0.0;
  if (walk.inColumn && walk.first.z > 0) {
    walkLoad(walk.first - ivec3(0, 0, 1), walk.cells);
    for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkBelow[i] = walkCell[i];
  }
  if (walk.inColumn && walk.first.z < walk.end) {
    walkLoad(walk.first, walk.cells);
    for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkCentre[i] = walkCell[i];
  }
  return walk;
}

// Reads the cell above plane z and stages plane z's tile with its halo; returns the invocation's
// cell on it. Every invocation of the group calls it (barriers).
ivec3 tiledWalkStage(TiledWalk walk, int z) {
  ivec3 cell = ivec3(walk.first.xy, z);
  ivec2 t = walk.t;
  for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkAbove[i] = 0.0;
  if (walk.inColumn && z + 1 < resolution.z) {
    walkLoad(cell + ivec3(0, 0, 1), walk.cells);
    for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkAbove[i] = walkCell[i];
  }
  barrier();  // every invocation has finished reading the previous plane
  if (walk.inColumn) {
    int slot = walkSlot(t);
    for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkPlane[slot + i] = walkCentre[i];
    // The halo: the tile's edge invocations stage the cells beyond it that lie in the grid.
    if (t.x == 0 && cell.x > 0) walkStageFromSource(cell - ivec3(1, 0, 0), t - ivec2(1, 0), walk.cells);
    if (t.x == TILE_X - 1 && cell.x + 1 < resolution.x)
      walkStageFromSource(cell + ivec3(1, 0, 0), t + ivec2(1, 0), walk.cells);
    if (t.y == 0 && cell.y > 0) walkStageFromSource(cell - ivec3(0, 1, 0), t - ivec2(0, 1), walk.cells);
    if (t.y == TILE_Y - 1 && cell.y + 1 < resolution.y)
      walkStageFromSource(cell + ivec3(0, 1, 0), t + ivec2(0, 1), walk.cells);
  }
  memoryBarrierShared();
  barrier();
  return cell;
}

// The light of the neighbour at `offset` (a unit axis step, inside the grid) into walkCell.
void tiledWalkNeighbour(TiledWalk walk, ivec3 offset) {
  if (offset.z != 0) {
    for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkCell[i] = offset.z < 0 ? walkBelow[i] : walkAbove[i];
  } else {
    int slot = walkSlot(walk.t + offset.xy);
    for (int i = 0; i < WALK_CELL_FLOATS; ++i) walkCell[i] = walkPlane[slot + i];
  }
}

// The column moves up a plane.
void tiledWalkAdvance() {
  for (int i = 0; i < WALK_CELL_FLOATS; ++i) {
    walkBelow[i] = walkCentre[i];
    walkCentre[i] = walkAbove[i];
  }
}

#endif
