#pragma once
// The tiled layout of standard gathering on GL (shaders/propagation/standard_gather_tiled.comp,
// [propagation] gpu_kernel = "tiled"): its work group per SH order, and what it reads.

#include <glm/glm.hpp>

namespace lpvlab {

namespace standard_tiled {
#include "shaders/propagation/standard_interface.glsl"
}

// The work group (x, y) for `coefficients` per channel. The shared tile holds (x + 2)(y + 2) cells
// of 3 x coefficients floats, and GL guarantees 32 KiB of shared memory
// (GL_MAX_COMPUTE_SHARED_MEMORY_SIZE): 32 x 4 at orders 1 and 2 (9.6 and 21.5 KiB; a warp of 32
// reads a whole row), 16 x 4 at order 3 (20.3 KiB; 32 x 4 would need 38.3).
inline glm::ivec2 standardTiledGroup(int coefficients) {
  return coefficients <= 9 ? glm::ivec2(32, 4) : glm::ivec2(16, 4);
}

// Source cells read from memory per cell-iteration: its own once, the halo of its tile again
// (2 (x + y) cells per x y), and the first plane of each z-span's walk again (it needs the plane
// below). Whole tiles: a grid's partial tiles read a little more. The simple kernel reads 6.
inline double standardTiledSourceReads(int coefficients) {
  const glm::dvec2 t(standardTiledGroup(coefficients));
  return 1.0 + 2.0 * (t.x + t.y) / (t.x * t.y) + 1.0 / standard_tiled::TILED_Z_SPAN;
}

// The bytes per cell-iteration the tiled layout does not read, against standard_work.h's six
// neighbour reads of 3 x coefficients floats.
inline double tiledSourceBytesSaved(int coefficients) {
  return 4.0 * 3 * coefficients * (6.0 - standardTiledSourceReads(coefficients));
}

}  // namespace lpvlab
