#pragma once
// Sky-column injection on the CPU (the CPU backend, strategy.h): every depth-map texel that meets
// a surface adds the downward lobe of the sky's light through its column top to the cell the
// shared functions of shaders/injection/sky_columns.glsl name (compiled as C++ in double
// precision), the very text the GL kernel runs. Without atomics: the texels over one grid column
// (x, z) all land in that column, so columns are summed in parallel, each in texel order, and
// the grid does not depend on the thread count.

#include <vector>

#include <glm/glm.hpp>

#include "framework/math/grid_geometry.h"

namespace lpvlab {

// `depth`: the top-down depth map, width x height texels, row by row (texel x + width * y), 1
// where no surface; `perTexel`: the sky's L a per channel (W/sr); `everyFreeCell`: the thesis's
// fill, every cell from the injection layer up to the grid's top (skyTopLayer). Adds to `grid`
// (grid.glsl layout, `coefficients` per channel). Throws an Error for a map that does not tile the grid's
// columns evenly (a whole number of texels per column along x and z).
void injectSkyColumnsCpu(const std::vector<float>& depth, int width, int height,
                         const GridGeometry& grid, int coefficients, float shiftCells,
                         const glm::vec3& perTexel, bool everyFreeCell, float* gridOut);

}  // namespace lpvlab
