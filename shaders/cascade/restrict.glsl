// Carrying a finer cascade level's injected light into its parent (thesis 5.1): every parent cell
// that lies wholly inside the child becomes the sum of its 2x2x2 child cells. The intensities
// (W/sr) of emitters in one cell add, so flux is conserved exactly, and the parent propagates the
// child's sources, placed to the child's precision (VPLs shifted by a child cell, not a parent
// cell), instead of its own coarser injection of the same surfaces. Parent cells outside the child
// keep their own. Shared subset: restrict.comp and the CPU carry (framework/pipeline/cascade.cpp)
// call this; the includer defines
//   real childCoefficient(int index)   the child grid's value at grid.glsl's coefficientIndex
#ifndef LPVLAB_RESTRICT_GLSL
#define LPVLAB_RESTRICT_GLSL
#include "../common/grid.glsl"

// Coefficient k of `channel` of the parent cell `c` (counted from the child's first cell, in
// parent cells); both levels have `resolution` cells.
real restrictedCoefficient(int channel, int k, int coefficients, ivec3 c, ivec3 resolution) {
  int cells = cellCount(resolution);
  real sum = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    sum += childCoefficient(coefficientIndex(channel, k, coefficients,
                                             cellIndex(2 * c + o, resolution), cells));
  }
  return sum;
}

#endif
