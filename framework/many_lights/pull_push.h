#pragma once
// The pull-push algorithm of seed 001, 3.3.1, filling the holes of a depth map whose texels are
// partly undefined (an imperfect shadow map's, where no point was splatted):
//   pull: from the finest level to the coarsest, each texel of the next coarser level (half the
//         side) is the average of its four finer texels that are defined; undefined if none is.
//         A level whose every texel is defined ends the pull (the seed's note: no coarser level is
//         needed), and so does `maxLevels` coarser levels made.
//   push: from the coarsest level made back to the finest, each undefined texel takes the value
//         of the texel under it in the next coarser level (already filled, unless undefined there
//         too).
// So a fully defined map is unchanged, and a hole gets the average of the defined texels of the
// nearest coarser block that has one.

#include <vector>

namespace lpvlab {

// `map`: size x size values, row by row; `undefined` marks a hole (a value no defined texel has,
// e.g. -1 among depths; not NaN, which equals nothing). size must be a power of two (an Error
// otherwise). `scratch` holds the coarser levels (kept by the caller, so repeated calls allocate
// nothing). Returns the coarser levels made (0: nothing to fill). Texels still undefined after it
// (a map with no defined texel, or holes wider than maxLevels reach) keep `undefined`.
int pullPush(float* map, int size, int maxLevels, float undefined, std::vector<float>& scratch);

}  // namespace lpvlab
