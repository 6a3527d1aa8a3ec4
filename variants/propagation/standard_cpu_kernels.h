#pragma once
// Standard propagation's CPU kernel, generic in its scalar type: the row kernels, compiled per
// instruction set, and the iteration that calls them (standard_cpu.h declares what they
// compute). Included only by the translation units that instantiate them, one scalar type each
// (standard_cpu.cpp: float, with the face tables and occlusion; standard_cpu_double.cpp;
// standard_cpu_gather_dual.cpp, whose row kernels standard_cpu_rows_dual_{4,9,16}.cpp compile),
// so that they compile in parallel: in one file they took over 12 minutes of one core while the
// build's other core waited. Everything here has internal linkage or is a template, so each of
// them gets its own copy; the dual row kernels are reached through the three functions below.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <vector>

#include "framework/core/cpu_dispatch.h"
#include "framework/core/cpu_features.h"
#include "framework/core/error.h"
#include "framework/math/dual.h"
#include "framework/math/shared.h"
#include "variants/propagation/standard_cpu.h"

#include "variants/propagation/cpu_rows.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/standard_faces.glsl"
LPVLAB_SHARED_GLSL_END
#include "variants/propagation/gv_lookup.h"

namespace lpvlab {

namespace {

// Which SH basis functions vanish on the face directions the kernel uses, known when it is
// compiled so that it skips their products. Each real SH basis function of sh.glsl up to order 3
// is a product of some of the direction's components (requiredAxes(k): every one of them must be
// non-zero), of x^2 - y^2 for k = 8 and 14 (anyOfAxes(k): one of x, y must be non-zero) and of a
// factor that is not zero on these directions. Bits: 1 x, 2 y, 4 z. A face direction has
// non-zero components only along the flow axis and, for a side face, along the face's normal, so
// Y_k vanishes there when it needs another axis. makeStandardFaceTable checks every skipped
// product against the shared GLSL (it must be exactly 0), so a change of sh.glsl or
// standard_faces.glsl that breaks this is an error, not a wrong image.
constexpr int requiredAxes(int k) {
  constexpr int x = 1, y = 2, z = 4;
  constexpr int axes[16] = {0, y, z, x, x | y, y | z, 0, x | z, 0, y, x | y | z, y, z, x, z, x};
  return axes[k];
}
constexpr int anyOfAxes(int k) { return k == 8 || k == 14 ? 1 | 2 : 0; }
constexpr int axisBit(int direction) { return 1 << (direction / 2); }
// Y_k is not identically zero on directions with non-zero components exactly `present`.
constexpr bool basisLivesOn(int k, int present) {
  return (requiredAxes(k) & ~present) == 0 && (anyOfAxes(k) == 0 || (anyOfAxes(k) & present) != 0);
}
// The face of the target with `normal` receives light from neighbour `direction`.
constexpr bool faceUsesBasis(int direction, int normal, int k) {
  return normal != direction && basisLivesOn(k, axisBit(direction) | axisBit(normal));
}
// The clamped-cosine lobe about the axis `normal` uses Y_k.
// (The clamped cosine has no band 3: shZonalCosine(3) = 0.)
constexpr bool lobeUsesBasis(int normal, int k) { return k < 9 && basisLivesOn(k, axisBit(normal)); }

}  // namespace

namespace {

// The row padding of the kernel (see gatherRegister's callers).
constexpr int kRowPadding = 16;

}  // namespace

namespace {

using cpu_rows::copyShortRun;
using cpu_rows::loadRegister;
using cpu_rows::RegisterOf;
using cpu_rows::select;
using cpu_rows::storeRegister;

// What the cells of one register of a target row, starting at x, receive, one channel: from each
// of the six neighbours (their rows, from[d][k * stride[d] + x]), through the five faces of a
// cell that neighbour's light enters. The fluxes are summed per face normal, then the six
// normals' lobes are added once, into out[k * width + x]; lanes are independent cells. Products
// with a basis function that vanishes on the face (faceUsesBasis) or the lobe (lobeUsesBasis)
// are skipped: the loops are unrolled, so the tests are resolved when compiling. A face's flux
// is added as f = max(f + intensity, f), which is f + max(intensity, 0) with the sum folded into
// the intensity's multiply-adds.
// Occluded: each face's flux is max(intensity, 0) times the face's transmittance, read from
// t[standardFaceSlot(d, normal) * tStride + x]. `only` >= 0: from that neighbour alone.
// Reprojects: the lanes whose cell reprojects in this iteration (ReprojectedCells, its row at
// `reprojected`) take the reprojected lobe instead.
template <class Real>
struct ReprojectedRow {
  const Real* since;       // the row's since[x]
  const Real* faceWeight;  // normal n's weights at faceWeight[n * stride + x]
  const Real* lobe;        // coefficient k's lobe at lobe[k * stride + x]
  std::size_t stride;
  Real iteration;
};

template <int N, int Bytes, bool Occluded, bool Reprojects, class Real>
[[gnu::always_inline]] inline void gatherRegister(const StandardFaceTable<Real>& table,
                                                  const Real* const (&from)[6],
                                                  const std::size_t (&stride)[6], int width, int x,
                                                  const Real* t, std::size_t tStride, int only,
                                                  const ReprojectedRow<Real>* reprojected,
                                                  Real* out) {
  using V = typename RegisterOf<Real, Bytes>::type;
  V fluxByNormal[6] = {};
#pragma GCC unroll 6
  for (int d = 0; d < 6; ++d) {
    if (only >= 0 && d != only) continue;
    V s[N];
#pragma GCC unroll 16
    for (int k = 0; k < N; ++k) s[k] = loadRegister<V>(from[d] + k * stride[d] + x);
#pragma GCC unroll 6
    for (int normal = 0; normal < 6; ++normal) {
      if (normal == d) continue;  // the shared face receives nothing
      if constexpr (Occluded) {
        V intensity = {};
#pragma GCC unroll 16
        for (int k = 0; k < N; ++k)
          if (faceUsesBasis(d, normal, k)) intensity += s[k] * table.scaledBasis[d][normal][k];
        const V zero = {};
        const V transmittance = loadRegister<V>(t + standardFaceSlot(d, normal) * tStride + x);
        fluxByNormal[normal] += transmittance * select(intensity > zero, intensity, zero);
      } else {
        V total = fluxByNormal[normal];
#pragma GCC unroll 16
        for (int k = 0; k < N; ++k)
          if (faceUsesBasis(d, normal, k)) total += s[k] * table.scaledBasis[d][normal][k];
        fluxByNormal[normal] = select(total > fluxByNormal[normal], total, fluxByNormal[normal]);
      }
    }
  }
  // Reprojecting lanes: r = sum_n flux_n faceWeight_n, re-emitted as r * lobe_k.
  [[maybe_unused]] V redirected = {};
  [[maybe_unused]] decltype(V{} < V{}) reprojecting{};
  if constexpr (Reprojects) {
    const V since = loadRegister<V>(reprojected->since + x);
    reprojecting = since <= reprojected->iteration;
#pragma GCC unroll 6
    for (int normal = 0; normal < 6; ++normal) {
      const V weight = loadRegister<V>(reprojected->faceWeight + normal * reprojected->stride + x);
      redirected += fluxByNormal[normal] * weight;
    }
  }
#pragma GCC unroll 16
  for (int k = 0; k < N; ++k) {
    V sum = {};
#pragma GCC unroll 6
    for (int normal = 0; normal < 6; ++normal)
      if (lobeUsesBasis(normal, k)) sum += fluxByNormal[normal] * table.normalLobe[normal][k];
    if constexpr (Reprojects) {
      V lobe = {};
      if (k < ReprojectedCells<Real>::kMaxLobeCoefficients)
        lobe = loadRegister<V>(reprojected->lobe + k * reprojected->stride + x);
      sum = select(reprojecting, redirected * lobe, sum);
    }
    storeRegister(out + k * width + x, sum);
  }
}

// What the GV's surfaces at the blocked outgoing faces of a row's cells re-emit into those cells,
// one channel, added to out[k * width + x]: per blocked face the intensity towards it (the row's
// own light, `own`: coefficient k of cell x at own[k * plane + x]) times the solid angle (the
// table's scaled basis), clamped, times albedo (1 - T), times the surfaces' lobe over pi
// (standard_faces.glsl's standardBlockedFlux and bounce lobe).
template <int N, class Real>
inline void addBounces(const StandardFaceTable<Real>& table, const StandardOcclusion<Real>& o,
                       int row, const Real* own, std::size_t plane, int channel, int width,
                       Real* out) {
  for (std::size_t i = o.firstBounce[std::size_t(row)]; i < o.firstBounce[std::size_t(row) + 1]; ++i) {
    const typename StandardOcclusion<Real>::Bounce& b = o.bounces[i];
    const Real* basis = table.scaledBasis[b.direction][b.normal];
    Real intensity(0);
    for (int k = 0; k < N; ++k) intensity += own[k * plane + std::size_t(b.x)] * basis[k];
    if (!(intensity > Real(0))) continue;
    const Real reemitted = b.weight[channel] * intensity;
    const Real* lobe = o.bounceLobes.data() + i * N;
    for (int k = 0; k < N; ++k) out[std::size_t(k) * width + b.x] += reemitted * lobe[k];
  }
}

}  // namespace

// How a row pass writes what it computed: gathering stores it and adds it to the accumulated
// grid (with the cell's source value too when the previous iteration deferred its addition, or
// not at all when this one defers), scattering's first pass stores it, the others add it (the
// accumulated grid once after). Outside the anonymous namespace: it is part of the row kernels'
// type, which the dual ones' functions below return across translation units.
enum class RowOutput { StoreAndAccumulate, StoreAndAccumulateWithSource, Store, Add };

namespace {

// The row's `cells` computed values written as `output` says into `to` (and `sum`, with the
// row's source values `own`), a register at a time (the compiler cannot prove the rows apart to
// vectorise the plain loop).
template <int Bytes, class Real>
[[gnu::always_inline]] inline void storeRow(const Real* computed, Real* to, Real* sum,
                                            const Real* own, int cells, RowOutput output) {
  using V = typename RegisterOf<Real, Bytes>::type;
  constexpr int kLanes = RegisterOf<Real, Bytes>::kLanes;
  int x = 0;
  for (; x + kLanes <= cells; x += kLanes) {
    V value = loadRegister<V>(computed + x);
    if (output == RowOutput::Add) {
      storeRegister(to + x, loadRegister<V>(to + x) + value);
      continue;
    }
    storeRegister(to + x, value);
    if (output == RowOutput::Store) continue;
    if (output == RowOutput::StoreAndAccumulateWithSource) value += loadRegister<V>(own + x);
    storeRegister(sum + x, loadRegister<V>(sum + x) + value);
  }
  for (; x < cells; ++x) {
    if (output == RowOutput::Add) {
      to[x] += computed[x];
      continue;
    }
    to[x] = computed[x];
    if (output == RowOutput::StoreAndAccumulate) sum[x] += computed[x];
    if (output == RowOutput::StoreAndAccumulateWithSource) sum[x] += computed[x] + own[x];
  }
}

// Target rows [rowBegin, rowEnd) (row = y + res.y * z), every channel, a register of cells at a
// time over the row padded to `width` cells (the cells past the row's end are computed and
// dropped). Each neighbour row is read where it lies when the padding's reads stay inside the
// grid; the two x neighbours are the row itself shifted by one cell, staged with a zero where the
// shift leaves the grid, and a neighbour row outside the grid (or one whose padded read would
// pass the grid's end) is read from a staged copy padded with zeros. A zero source sends
// max(0, 0) = 0 through every face, so the loop needs no test for the grid's edges. Each target
// cell is then stored once and added to `accumulated`. With `occlusion`, the faces' fluxes are
// attenuated and the row's bounces added before storing. A scattering pass (`only` >= 0) takes
// the light of neighbour `only` alone and writes as `output` says (the bounces in the first pass).
// With `reprojected`, its cells that reproject in iteration `iteration` do.
template <int N, int Bytes, class Real>
[[gnu::always_inline]] inline void gatherRowsImpl(
    const StandardFaceTable<Real>& table, const glm::ivec3& res, const Real* source, Real* target,
    Real* accumulated, int rowBegin, int rowEnd, const StandardOcclusion<Real>* occlusion, int only,
    RowOutput output, const ReprojectedCells<Real>* reprojected, int iteration) {
  const std::size_t plane = std::size_t(res.x) * res.y * res.z;  // cells: one coefficient's span
  const Real* const sourceEnd = source + 3 * N * plane;
  const int width = standardCpuRowWidth(res.x);
  const std::size_t staged = std::size_t(N) * width;
  // Per direction a staged row, whose cells outside [first, last) below stay zero: they are never
  // written. And one row of zeros for the neighbours outside the grid.
  std::vector<Real> stage(6 * staged, Real(0));
  const std::vector<Real> zeros(staged, Real(0));
  std::vector<Real> out(staged);
  const int rows = res.y * res.z;
  for (int row = rowBegin; row < rowEnd; ++row) {
    const int y = row % res.y, z = row / res.y;
    const std::size_t base = std::size_t(row) * res.x;
    // The next row's new data, every channel and coefficient, asked for a row ahead: its +y and
    // +z neighbour rows (the others were read by earlier rows) and its target and accumulated
    // rows. A row reads and writes about 7 x 3N streams, more than the hardware prefetchers
    // follow (64^3 order 1: 3.1 -> 2.7-2.85 ms an iteration).
    if (row + 1 < rows) {
      const int nextY = (row + 1) % res.y, nextZ = (row + 1) / res.y;
      const std::size_t next = std::size_t(row + 1) * res.x;
      const std::size_t nextY1 = next + std::size_t(res.x), nextZ1 = next + std::size_t(res.y) * res.x;
      const bool accumulates = output == RowOutput::StoreAndAccumulate ||
                               output == RowOutput::StoreAndAccumulateWithSource;
      constexpr int kLine = 64 / int(sizeof(Real));
      for (std::size_t c = 0; c < std::size_t(3 * N); ++c)
        for (int x = 0; x < res.x; x += kLine) {
          if (nextY + 1 < res.y) __builtin_prefetch(source + c * plane + nextY1 + x, 0, 3);
          if (nextZ + 1 < res.z) __builtin_prefetch(source + c * plane + nextZ1 + x, 0, 3);
          __builtin_prefetch(target + c * plane + next + x, 1, 3);
          if (accumulates) __builtin_prefetch(accumulated + c * plane + next + x, 1, 3);
        }
    }
    for (int channel = 0; channel < 3; ++channel) {
      const std::size_t channelBase = std::size_t(channel) * N * plane;
      const Real* from[6];
      std::size_t stride[6];
      for (int d = 0; d < 6; ++d) {
        const glm::ivec3 o = table.offset[d];
        Real* copy = stage.data() + d * staged;
        stride[d] = std::size_t(width);
        if ((only >= 0 && d != only) || y + o.y < 0 || y + o.y >= res.y || z + o.z < 0 ||
            z + o.z >= res.z) {
          from[d] = zeros.data();
          continue;
        }
        from[d] = copy;
        const Real* neighbourRow =
            source + channelBase + (std::size_t(z + o.z) * res.y + (y + o.y)) * res.x;
        if (o.x == 0 && neighbourRow + (N - 1) * plane + width <= sourceEnd) {
          from[d] = neighbourRow;
          stride[d] = plane;
          continue;
        }
        // Cell x of the staged row is the neighbour's cell x + o.x, where that lies in the row.
        const int first = std::max(0, -o.x), last = std::min(res.x, res.x - o.x);  // [first, last)
        for (int k = 0; k < N; ++k)
          copyShortRun(neighbourRow + k * plane + first + o.x, copy + std::size_t(k) * width + first,
                       last - first);
      }
      const std::size_t rowStride = std::size_t(rows) * width;
      const Real* t =
          occlusion ? occlusion->transmittance.data() + std::size_t(row) * width : nullptr;
      ReprojectedRow<Real> reprojectedRow{};
      if (reprojected)
        reprojectedRow = {reprojected->since.data() + std::size_t(row) * width,
                          reprojected->faceWeight.data() + std::size_t(row) * width,
                          reprojected->lobe.data() + std::size_t(row) * width, rowStride,
                          Real(iteration)};
      // The row's four kinds of register, chosen once per row.
      const auto registers = [&]<bool Occluded, bool Reprojects>() {
        for (int x = 0; x < width; x += RegisterOf<Real, Bytes>::kLanes)
          gatherRegister<N, Bytes, Occluded, Reprojects>(
              table, from, stride, width, x, t, rowStride, only, &reprojectedRow, out.data());
      };
      if (occlusion && reprojected)
        registers.template operator()<true, true>();
      else if (occlusion)
        registers.template operator()<true, false>();
      else if (reprojected)
        registers.template operator()<false, true>();
      else
        registers.template operator()<false, false>();
      if (occlusion && output != RowOutput::Add)
        addBounces<N>(table, *occlusion, row, source + channelBase + base, plane, channel, width,
                      out.data());
      for (int k = 0; k < N; ++k)
        storeRow<Bytes>(out.data() + std::size_t(k) * width,
                        target + channelBase + k * plane + base,
                        accumulated + channelBase + k * plane + base,
                        source + channelBase + k * plane + base, res.x, output);
    }
  }
}

template <class Real>
using RowsFunction = void (*)(const StandardFaceTable<Real>&, const glm::ivec3&, const Real*, Real*,
                              Real*, int, int, const StandardOcclusion<Real>*, int, RowOutput,
                              const ReprojectedCells<Real>*, int);

// The row loop compiled for each instruction set with its register width (the inlined body takes
// the function's target).
#define LPVLAB_GATHER_ROWS(name, bytes, attributes)                                                \
  template <int N, class Real>                                                                     \
  attributes void name(const StandardFaceTable<Real>& table, const glm::ivec3& res,                \
                       const Real* source, Real* target, Real* accumulated, int begin, int end,    \
                       const StandardOcclusion<Real>* occlusion, int only, RowOutput output,       \
                       const ReprojectedCells<Real>* reprojected, int iteration) {                 \
    gatherRowsImpl<N, bytes>(table, res, source, target, accumulated, begin, end, occlusion, only, \
                             output, reprojected, iteration);                                      \
  }
LPVLAB_GATHER_ROWS(gatherRowsX86_64, 16, )
LPVLAB_GATHER_ROWS(gatherRowsV3, 32, __attribute__((target("arch=x86-64-v3"))))
LPVLAB_GATHER_ROWS(gatherRowsV4, 64, __attribute__((target("arch=x86-64-v4"))))
#undef LPVLAB_GATHER_ROWS

// The levels and their names are cpu_dispatch.h's, which the per-pixel kernels use too.
inline bool cpuRunsKernel(const std::string& isa) {
  for (const CpuKernelLevel level : cpuKernelLevelsThisCpuRuns())
    if (isa == cpuKernelLevelName(level)) return true;
  return false;
}

// double is the tests' reference precision, never a run's: its rows are compiled for x86-64 alone
// (each wider build of the row kernels costs minutes of compiling and would test nothing more).
template <int N, class Real>
RowsFunction<Real> rowsFor(const std::string& isa) {
  if constexpr (!std::is_same_v<Real, double>) {
    if (isa == "x86-64-v4") return gatherRowsV4<N, Real>;
    if (isa == "x86-64-v3") return gatherRowsV3<N, Real>;
  }
  return gatherRowsX86_64<N, Real>;
}

// Called once per iteration: "auto" (the pipeline's choice) is resolved once per process.
inline const std::string& resolveIsa(const std::string& isa) {
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

// The dual-number row kernels, one translation unit per SH order
// (standard_cpu_rows_dual_<coefficients>.cpp): on dual numbers each takes minutes to compile, and
// apart they compile in parallel (together, one file, they were the build's last 13 minutes).
RowsFunction<Dual> standardDualRows4(const std::string& isa);
RowsFunction<Dual> standardDualRows9(const std::string& isa);
RowsFunction<Dual> standardDualRows16(const std::string& isa);

namespace {

// The row kernel for `coefficients` on `isa`: compiled in this translation unit, or for dual
// numbers in its own (above).
template <class Real>
RowsFunction<Real> rowsForCoefficients(int coefficients, const std::string& isa) {
  if constexpr (std::is_same_v<Real, Dual>) {
    return coefficients == 4 ? standardDualRows4(isa)
           : coefficients == 9 ? standardDualRows9(isa) : standardDualRows16(isa);
  } else {
    return coefficients == 4 ? rowsFor<4, Real>(isa)
           : coefficients == 9 ? rowsFor<9, Real>(isa) : rowsFor<16, Real>(isa);
  }
}

// One iteration, gathering (one pass over the target rows) or scattering (six passes, one per
// neighbour direction; see standardScatterCpu).
template <class Real>
void propagateCpu(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
                  const Real* source, Real* target, Real* accumulated, const std::string& isa,
                  int threads, const StandardOcclusion<Real>* occlusion,
                  StepAccumulation accumulation, bool scatter,
                  const ReprojectedCells<Real>* reprojected, int iteration) {
  if (glm::any(glm::lessThan(resolution, glm::ivec3(1))))
    throw Error("standard propagation (CPU): grid resolution must be at least 1 per axis");
  if (occlusion && (occlusion->resolution != resolution || occlusion->coefficients != table.coefficients))
    throw Error("standard propagation (CPU): the geometry volume's faces were made for another grid");
  if (reprojected &&
      (reprojected->resolution != resolution || reprojected->coefficients != table.coefficients))
    throw Error("standard propagation (CPU): the reprojected cells were made for another grid");
  const std::string& chosen = resolveIsa(isa);
  RowsFunction<Real> rows = rowsForCoefficients<Real>(table.coefficients, chosen);
  const int rowCount = resolution.y * resolution.z;
  const auto pass = [&](int only, RowOutput output) {
    tbb::parallel_for(tbb::blocked_range<int>(0, rowCount), [&](const tbb::blocked_range<int>& r) {
      rows(table, resolution, source, target, accumulated, r.begin(), r.end(), occlusion, only,
           output, reprojected, iteration);
    });
  };
  auto work = [&] {
    if (!scatter)
      return pass(-1, accumulation == StepAccumulation::Target ? RowOutput::StoreAndAccumulate
                      : accumulation == StepAccumulation::Deferred
                          ? RowOutput::Store
                          : RowOutput::StoreAndAccumulateWithSource);
    for (int direction = 0; direction < 6; ++direction)
      pass(direction, direction == 0 ? RowOutput::Store : RowOutput::Add);
    if (accumulation == StepAccumulation::Deferred) return;
    const bool withSource = accumulation == StepAccumulation::SourceAndTarget;
    const std::size_t floats = std::size_t(3) * table.coefficients * rowCount * resolution.x;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, floats),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        Real* __restrict sum = accumulated;
                        const Real* __restrict add = target;
                        const Real* __restrict previous = source;
                        if (withSource)
                          for (std::size_t i = r.begin(); i < r.end(); ++i) sum[i] += add[i] + previous[i];
                        else
                          for (std::size_t i = r.begin(); i < r.end(); ++i) sum[i] += add[i];
                      });
  };
  if (threads > 0) {
    tbb::task_arena arena(threads);
    arena.execute(work);
  } else {
    work();
  }
}

}  // namespace

template <class Real>
void standardGatherCpu(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
                       const Real* source, Real* target, Real* accumulated, const std::string& isa,
                       int threads, const StandardOcclusion<Real>* occlusion,
                       StepAccumulation accumulation, const ReprojectedCells<Real>* reprojected,
                       int iteration) {
  propagateCpu(table, resolution, source, target, accumulated, isa, threads, occlusion,
               accumulation, false, reprojected, iteration);
}

template <class Real>
void standardScatterCpu(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
                        const Real* source, Real* target, Real* accumulated,
                        const std::string& isa, int threads,
                        const StandardOcclusion<Real>* occlusion,
                        StepAccumulation accumulation) {
  propagateCpu(table, resolution, source, target, accumulated, isa, threads, occlusion,
               accumulation, true, static_cast<const ReprojectedCells<Real>*>(nullptr), 0);
}
}  // namespace lpvlab
