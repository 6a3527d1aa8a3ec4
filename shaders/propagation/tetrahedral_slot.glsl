// The lattice cell of a tetrahedral kernel's invocation: kernels run over (12 res.x, res.y,
// res.z), x = cube.x * 12 + code, so every dispatch dimension stays within the grid's.
#ifndef LPVLAB_TETRAHEDRAL_SLOT_GLSL
#define LPVLAB_TETRAHEDRAL_SLOT_GLSL
#include "tetrahedral_lattice.glsl"

ivec4 tetOfInvocation(uvec3 id) {
  ivec3 g = ivec3(id);
  return ivec4(g.x / TET_PER_CUBE, g.y, g.z, g.x - TET_PER_CUBE * (g.x / TET_PER_CUBE));
}

#endif
