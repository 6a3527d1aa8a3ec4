#include "variants/propagation/standard_cpu.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "framework/core/cpu_features.h"
#include "framework/core/error.h"
#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/standard_faces.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

template <class Real>
StandardFaceTable<Real> makeStandardFaceTable(int shOrder, double farSolidAngle,
                                              double sideSolidAngle) {
  if (shOrder < 1 || shOrder > 3)
    throw Error("standard propagation (CPU): SH order " + std::to_string(shOrder) +
                " is not 1, 2 or 3");
  for (double omega : {farSolidAngle, sideSolidAngle})
    if (!(omega >= 0.0) || !std::isfinite(omega))
      throw Error("standard propagation (CPU): face solid angle " + std::to_string(omega) +
                  " is not a finite non-negative number");
  constexpr int kDirections = StandardFaceTable<Real>::kDirections;
  StandardFaceTable<Real> table{};
  table.coefficients = (shOrder + 1) * (shOrder + 1);
  glm::ivec3 axes[kDirections];  // +x, -x, +y, -y, +z, -z
  for (int i = 0; i < kDirections; ++i) {
    axes[i] = glm::ivec3(0);
    axes[i][i / 2] = i % 2 == 0 ? 1 : -1;
  }
  for (int normal = 0; normal < kDirections; ++normal)
    for (int k = 0; k < table.coefficients; ++k)
      table.normalLobe[normal][k] = Real(shared::shCosineLobeAt(k, glm::dvec3(axes[normal])) / shared::PI);
  for (int direction = 0; direction < kDirections; ++direction) {
    table.offset[direction] = axes[direction];
    const glm::dvec3 d = -glm::dvec3(axes[direction]);  // light flows from the neighbour along -offset
    bool filled[kDirections] = {};
    for (int f = 0; f < shared::STANDARD_FACES; ++f) {
      // The face's normal is an axis (standard_faces.glsl): file the face under it.
      const glm::dvec3 n = shared::standardFaceNormal(d, f);
      const int normal = int(std::find_if(axes, axes + kDirections, [&](const glm::ivec3& a) {
                           return glm::dvec3(a) == n;
                         }) - axes);
      if (normal == kDirections || normal == direction || filled[normal])
        throw Error("standard propagation (CPU): face normals are not the five axes the kernel "
                    "expects (standard_faces.glsl changed?)");
      filled[normal] = true;
      const glm::dvec3 w = shared::standardFaceDirection(d, f);
      const double omega = shared::standardFaceSolidAngle(f, farSolidAngle, sideSolidAngle);
      for (int k = 0; k < table.coefficients; ++k)
        table.scaledBasis[direction][normal][k] = Real(omega * shared::shBasisAt(k, w));
    }
  }
  return table;
}

template StandardFaceTable<float> makeStandardFaceTable<float>(int, double, double);
template StandardFaceTable<double> makeStandardFaceTable<double>(int, double, double);

namespace {

// What one cell of a target row receives, one channel: from each of the six neighbours (its
// coefficients at from[d][k * plane + x], already offset to the neighbour's x), through the five
// faces of this cell that neighbour's light enters, weighted by present[d] (0 for a neighbour
// outside the grid, whose pointer then points at readable memory). The fluxes are summed per
// face normal, then the six normals' lobes are added once. Written to `target` and added to
// `accumulated`: each cell's coefficients are stored once per iteration.
template <int N, class Real>
[[gnu::always_inline]] inline void gatherCell(const StandardFaceTable<Real>& table,
                                              const Real* const (&from)[6],
                                              const Real (&present)[6], std::size_t plane, int x,
                                              Real* target, Real* accumulated) {
  Real fluxByNormal[6] = {};
#pragma GCC unroll 6
  for (int d = 0; d < 6; ++d) {
    Real s[N];
#pragma GCC unroll 16
    for (int k = 0; k < N; ++k) s[k] = from[d][k * plane + x];
#pragma GCC unroll 6
    for (int normal = 0; normal < 6; ++normal) {
      if (normal == d) continue;  // the shared face receives nothing
      Real intensity = Real(0);
#pragma GCC unroll 16
      for (int k = 0; k < N; ++k) intensity += s[k] * table.scaledBasis[d][normal][k];
      fluxByNormal[normal] += std::max(intensity, Real(0)) * present[d];
    }
  }
#pragma GCC unroll 16
  for (int k = 0; k < N; ++k) {
    Real out = Real(0);
#pragma GCC unroll 6
    for (int normal = 0; normal < 6; ++normal) out += fluxByNormal[normal] * table.normalLobe[normal][k];
    target[k * plane + x] = out;
    accumulated[k * plane + x] += out;
  }
}

// Target rows [rowBegin, rowEnd) (row = y + res.y * z), every channel. The inner x loop is
// straight-line code (every inner loop unrolled) and vectorises along x; `omp simd`
// (-fopenmp-simd: no OpenMP runtime) asserts the rows don't alias. The two end cells of a row,
// whose x neighbour lies outside, are done on their own.
template <int N, class Real>
[[gnu::always_inline]] inline void gatherRowsImpl(const StandardFaceTable<Real>& table,
                                                  const glm::ivec3& res, const Real* source,
                                                  Real* target, Real* accumulated, int rowBegin,
                                                  int rowEnd) {
  const std::size_t plane = std::size_t(res.x) * res.y * res.z;  // cells: one coefficient's span
  for (int row = rowBegin; row < rowEnd; ++row) {
    const int y = row % res.y, z = row / res.y;
    const std::size_t base = std::size_t(row) * res.x;
    for (int channel = 0; channel < 3; ++channel) {
      const std::size_t channelBase = std::size_t(channel) * N * plane;
      const Real* own = source + channelBase + base;
      const Real* from[6];
      Real present[6];
      for (int d = 0; d < 6; ++d) {
        const glm::ivec3 o = table.offset[d];
        const bool inside = y + o.y >= 0 && y + o.y < res.y && z + o.z >= 0 && z + o.z < res.z;
        present[d] = inside ? Real(1) : Real(0);
        from[d] = inside ? source + channelBase + (std::size_t(z + o.z) * res.y + (y + o.y)) * res.x + o.x
                         : own;
      }
      Real* to = target + channelBase + base;
      Real* sum = accumulated + channelBase + base;
#pragma omp simd
      for (int x = 1; x < res.x - 1; ++x) gatherCell<N>(table, from, present, plane, x, to, sum);
      // The row's ends (one cell when the row has one): an x neighbour outside the grid is
      // read at the cell itself, weighted 0.
      const int last = res.x - 1;
      for (int x = 0; x <= last; x += std::max(last, 1)) {
        const Real* edgeFrom[6];
        Real edgePresent[6];
        for (int d = 0; d < 6; ++d) {
          const int nx = x + table.offset[d].x;
          const bool inside = nx >= 0 && nx < res.x;
          edgeFrom[d] = inside ? from[d] : own;
          edgePresent[d] = inside ? present[d] : Real(0);
        }
        gatherCell<N>(table, edgeFrom, edgePresent, plane, x, to, sum);
      }
    }
  }
}

template <class Real>
using RowsFunction = void (*)(const StandardFaceTable<Real>&, const glm::ivec3&, const Real*,
                              Real*, Real*, int, int);

// The row loop compiled for each instruction set (the inlined body takes the function's target).
#define LPVLAB_GATHER_ROWS(name, attributes)                                                    \
  template <int N, class Real>                                                                  \
  attributes void name(const StandardFaceTable<Real>& table, const glm::ivec3& res,             \
                       const Real* source, Real* target, Real* accumulated, int begin, int end) { \
    gatherRowsImpl<N>(table, res, source, target, accumulated, begin, end);                     \
  }
LPVLAB_GATHER_ROWS(gatherRowsX86_64, )
LPVLAB_GATHER_ROWS(gatherRowsV3, __attribute__((target("arch=x86-64-v3"))))
LPVLAB_GATHER_ROWS(gatherRowsV4, __attribute__((target("arch=x86-64-v4"))))
#undef LPVLAB_GATHER_ROWS

bool cpuRunsKernel(const std::string& isa) {
  if (isa == "x86-64") return true;
  if (isa == "x86-64-v3") return cpuHasX86_64_v3();
  if (isa == "x86-64-v4") return cpuHasX86_64_v4();
  return false;
}

template <int N, class Real>
RowsFunction<Real> rowsFor(const std::string& isa) {
  if (isa == "x86-64-v4") return gatherRowsV4<N, Real>;
  if (isa == "x86-64-v3") return gatherRowsV3<N, Real>;
  return gatherRowsX86_64<N, Real>;
}

// Called once per iteration: "auto" (the pipeline's choice) is resolved once per process.
const std::string& resolveIsa(const std::string& isa) {
  static const std::string widest = supportedCpuKernelInstructionSets().back();
  if (isa == "auto") return widest;
  const auto& all = cpuKernelInstructionSets();
  if (std::find(all.begin(), all.end(), isa) == all.end())
    throw Error("standard propagation (CPU): instruction set '" + isa +
                "' is not one of auto, x86-64, x86-64-v3, x86-64-v4");
  if (!cpuRunsKernel(isa))
    throw Error("standard propagation (CPU): this CPU lacks instruction set '" + isa + "'");
  return isa;
}

}  // namespace

const std::vector<std::string>& cpuKernelInstructionSets() {
  static const std::vector<std::string> sets = {"x86-64", "x86-64-v3", "x86-64-v4"};
  return sets;
}

std::vector<std::string> supportedCpuKernelInstructionSets() {
  return namesThisCpuRuns(cpuKernelInstructionSets(), cpuRunsKernel);
}

template <class Real>
void standardGatherCpu(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
                       const Real* source, Real* target, Real* accumulated, const std::string& isa,
                       int threads) {
  if (glm::any(glm::lessThan(resolution, glm::ivec3(1))))
    throw Error("standard propagation (CPU): grid resolution must be at least 1 per axis");
  const std::string& chosen = resolveIsa(isa);
  RowsFunction<Real> rows = table.coefficients == 4   ? rowsFor<4, Real>(chosen)
                            : table.coefficients == 9 ? rowsFor<9, Real>(chosen)
                                                      : rowsFor<16, Real>(chosen);
  const int rowCount = resolution.y * resolution.z;
  auto work = [&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, rowCount), [&](const tbb::blocked_range<int>& r) {
      rows(table, resolution, source, target, accumulated, r.begin(), r.end());
    });
  };
  if (threads > 0) {
    tbb::task_arena arena(threads);
    arena.execute(work);
  } else {
    work();
  }
}

template void standardGatherCpu<float>(const StandardFaceTable<float>&, const glm::ivec3&,
                                       const float*, float*, float*, const std::string&, int);
template void standardGatherCpu<double>(const StandardFaceTable<double>&, const glm::ivec3&,
                                        const double*, double*, double*, const std::string&, int);

}  // namespace lpvlab
