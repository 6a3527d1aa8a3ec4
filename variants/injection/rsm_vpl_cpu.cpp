#include "variants/injection/rsm_vpl_cpu.h"

#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/buckets.h"
#include "framework/core/cpu_dispatch.h"
#include "framework/core/error.h"
#define LPVLAB_SHARED_SINGLE_PRECISION 1
#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/injection/vpl.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace {

// What the per-cell sums read and write.
struct CellSums {
  const RsmImages& rsm;
  const Buckets& byCell;  // the texels sorted by cell
  int cells;
  float* coefficients;
  float* normals;  // or null
};

// Cells [begin, end) add their VPLs, in texel order: each lobe in single precision, as GL finds
// it, summed in double precision (a cell can hold thousands of VPLs). Run at the instruction-set
// level asked for (cpu_dispatch.h), everything inlined, so the shared lobe's loop over the N
// coefficients per channel, known when compiling, unrolls.
template <int N>
void sumCells(const CellSums& s, int begin, int end) {
  for (int cell = begin; cell < end; ++cell) {
    const std::size_t from = s.byCell.first[std::size_t(cell)];
    const std::size_t to = s.byCell.first[std::size_t(cell) + 1];
    if (from == to) continue;
    double sum[3][N] = {};
    glm::dvec4 normal(0.0);
    for (std::size_t i = from; i < to; ++i) {
      const std::size_t t = s.byCell.order[i];
      const glm::vec3 n(s.rsm.normal->texels[t]);
      const glm::dvec3 phi(s.rsm.flux->texels[t]);
      for (int k = 0; k < N; ++k) {  // channels by name: GLM's phi[channel] is a branch
        const double lobe = shared::vplLobeAt(k, n);
        sum[0][k] += phi.x * lobe;
        sum[1][k] += phi.y * lobe;
        sum[2][k] += phi.z * lobe;
      }
      const double weight = phi.x + phi.y + phi.z;
      normal += glm::dvec4(weight * glm::dvec3(n), weight);
    }
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < N; ++k)
        s.coefficients[shared::coefficientIndex(channel, k, N, cell, s.cells)] += float(sum[channel][k]);
    if (s.normals)
      for (int c = 0; c < 4; ++c) s.normals[std::size_t(cell) * 4 + c] += float(normal[c]);
  }
}

}  // namespace

void injectRsmVplsCpu(const RsmImages& rsm, const GridGeometry& grid, int coefficients,
                      float shiftCells, float* coefficientsOut, float* normals,
                      CpuKernelLevel instructions) {
  const std::size_t texels = rsm.position->texels.size();
  if (rsm.normal->texels.size() != texels || rsm.flux->texels.size() != texels)
    throw Error("RSM injection (CPU): the RSM's images differ in size");
  if (coefficients != 4 && coefficients != 9 && coefficients != 16)
    throw Error("RSM injection (CPU): " + std::to_string(coefficients) +
                " SH coefficients per channel is not 4, 9 or 16");
  const int cells = grid.cellCount();

  // Each texel's cell, or -1 (not covered, or outside the grid).
  std::vector<int> cellOf(texels, -1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, texels), [&](const tbb::blocked_range<std::size_t>& r) {
    runAtLevel(instructions, [&] {
      for (std::size_t t = r.begin(); t < r.end(); ++t) {
        if (rsm.flux->texels[t].w == 0.0f) continue;
        const glm::ivec3 cell = shared::vplCell(glm::vec3(rsm.position->texels[t]),
                                                glm::vec3(rsm.normal->texels[t]), grid.origin,
                                                grid.cellSize, shiftCells);
        if (shared::cellInside(cell, grid.resolution)) cellOf[t] = shared::cellIndex(cell, grid.resolution);
      }
    });
  });

  // The texels sorted by cell, in texel order within a cell.
  const Buckets byCell = bucketByKey(cellOf, cells);

  // Each cell sums its VPLs.
  const CellSums sums{rsm, byCell, cells, coefficientsOut, normals};
  tbb::parallel_for(tbb::blocked_range<int>(0, cells), [&](const tbb::blocked_range<int>& r) {
    runAtLevel(instructions, [&] {
      switch (coefficients) {
        case 4: return sumCells<4>(sums, r.begin(), r.end());
        case 9: return sumCells<9>(sums, r.begin(), r.end());
        default: return sumCells<16>(sums, r.begin(), r.end());
      }
    });
  });
}

}  // namespace lpvlab
