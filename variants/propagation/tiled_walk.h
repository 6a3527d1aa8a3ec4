#pragma once
// The tiled gathers' walk on GL (shaders/propagation/tiled_walk.glsl; [propagation] gpu_kernel =
// "tiled" of standard and directed propagation): its work group per SH order, how it is
// dispatched, and what it reads.

#include <glad/gl.h>
#include <glm/glm.hpp>

#include "framework/gl/dispatch.h"

namespace lpvlab {

namespace tiled_walk {
#include "shaders/propagation/tiled_walk_interface.glsl"
}

// The work group (x, y) for `coefficients` per channel. The shared tile holds (x + 2)(y + 2) cells
// of 3 x coefficients floats, and GL guarantees 32 KiB of shared memory
// (GL_MAX_COMPUTE_SHARED_MEMORY_SIZE): 32 x 4 at orders 1 and 2 (9.6 and 21.5 KiB; a warp of 32
// reads a whole row), 16 x 4 at order 3 (20.3 KiB; 32 x 4 would need 38.3).
inline glm::ivec2 tiledWalkGroup(int coefficients) {
  return coefficients <= 9 ? glm::ivec2(32, 4) : glm::ivec2(16, 4);
}

// One step over a grid of `resolution`: a group per tile and z-span, of the kernel in use.
inline void dispatchTiledWalk(const glm::ivec3& resolution, const glm::ivec2& tile) {
  using namespace tiled_walk;
  const int spans = (resolution.z + TILED_Z_SPAN - 1) / TILED_Z_SPAN;
  dispatchCovering({resolution.x, resolution.y, spans}, {tile.x, tile.y, TILED_GROUP_SIZE_Z},
                   GL_SHADER_STORAGE_BARRIER_BIT);
}

// Source cells read from memory per cell-iteration: its own once, the halo of its tile again
// (2 (x + y) cells per x y), and the first plane of each z-span's walk again (it needs the plane
// below). Whole tiles: a grid's partial tiles read a little more. The simple kernels read 6.
inline double tiledWalkSourceReads(int coefficients) {
  const glm::dvec2 t(tiledWalkGroup(coefficients));
  return 1.0 + 2.0 * (t.x + t.y) / (t.x * t.y) + 1.0 / tiled_walk::TILED_Z_SPAN;
}

// The bytes per cell-iteration the tiled walk does not read, against six neighbour reads of
// 3 x coefficients floats.
inline double tiledWalkBytesSaved(int coefficients) {
  return 4.0 * 3 * coefficients * (6.0 - tiledWalkSourceReads(coefficients));
}

}  // namespace lpvlab
