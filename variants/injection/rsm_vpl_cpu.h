#pragma once
// RSM injection on the CPU (the CPU backend, strategy.h): every covered RSM texel becomes a VPL
// through the shared functions of shaders/injection/vpl.glsl (compiled as C++ in single
// precision, as GL runs them; the sums in double), the very text the GL kernel runs. Without
// atomics: each texel's cell is found (in parallel), the texels are sorted by cell keeping
// texel order (a counting sort), and each cell then sums its VPLs in that order (in parallel over
// cells), so the grid does not depend on the thread count. With a normal grid (directed propagation) each cell also gets
// (sum Phi n, sum Phi), Phi summed over RGB, as the GL kernel adds.

#include <vector>

#include "framework/core/cpu_dispatch.h"
#include "framework/math/grid_geometry.h"
#include "framework/pipeline/host_readback.h"

namespace lpvlab {

// Adds the VPLs of every layer of `rsm` to `grid` (grid.glsl layout, `coefficients` per channel)
// and, if `normals` is not null, to the normal grid (vec4 per cell). Throws an Error for images
// of different sizes. `instructions`: the level its loops run at (cpu_dispatch.h).
void injectRsmVplsCpu(const RsmImages& rsm, const GridGeometry& grid, int coefficients,
                      float shiftCells, float* coefficientsOut, float* normals,
                      CpuKernelLevel instructions = pixelKernelLevel());

}  // namespace lpvlab
