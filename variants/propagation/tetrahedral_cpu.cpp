#include "variants/propagation/tetrahedral_cpu.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <type_traits>

#include "framework/core/error.h"
#include "framework/math/dual.h"
#include "framework/math/shared.h"
#include "framework/math/tetrahedral_face_integrals.h"
#include "framework/math/tetrahedral_solid_angles.h"

#include "variants/propagation/cpu_rows.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END
#include "variants/propagation/gv_lookup.h"

namespace lpvlab {

namespace {

constexpr int kCodes = shared::TET_PER_CUBE,
              kFaces = shared::TET_FACES;  // tetrahedral_lattice.glsl
constexpr int kRowPadding = 16;  // rows are a whole number of registers at every width

}  // namespace

template <class Real>
TetrahedralTable<Real> makeTetrahedralTable(int shOrder, bool faceIntegrals) {
  if (shOrder < 1 || shOrder > 3)
    throw Error("tetrahedral propagation (CPU): SH order " + std::to_string(shOrder) +
                " is not 1, 2 or 3");
  TetrahedralTable<Real> table{};
  table.coefficients = (shOrder + 1) * (shOrder + 1);
  const TetrahedralFaceSolidAngles angles = tetrahedralFaceSolidAngles();
  const std::vector<double>& integrals = tetrahedralFaceIntegrals();
  for (int code = 0; code < kCodes; ++code) {
    for (int k = 0; k < kFaces; ++k)
      for (int i = 0; i < table.coefficients; ++i)
        table.lobe[code][k][i] =
            Real(shared::shCosineLobeAt(i, shared::tetFaceNormal(code, k)) / shared::PI);
    for (int j = 0; j < kFaces; ++j) {
      const glm::ivec4 n = shared::tetNeighbour(glm::ivec4(0, 0, 0, code), j);
      table.neighbourOffset[code][j] = glm::ivec3(n);
      table.neighbourCode[code][j] = n.w;
      for (int k = 0; k < kFaces; ++k) {
        if (k == j) continue;
        const glm::dvec3 direction = shared::tetFarFaceDirection(code, j, k);
        const double solidAngle =
            shared::tetFarFaceSolidAngle(j, k, angles.smallFace, angles.largeFace);
        for (int i = 0; i < table.coefficients; ++i)
          table.weight[code][j][k][i] = Real(
              faceIntegrals ? integrals[std::size_t(shared::tetFaceIntegralIndex(code, j, k, i))]
                            : solidAngle * shared::shBasisAt(i, direction));
      }
    }
  }
  return table;
}

template TetrahedralTable<float> makeTetrahedralTable<float>(int, bool);
template TetrahedralTable<double> makeTetrahedralTable<double>(int, bool);
template TetrahedralTable<Dual> makeTetrahedralTable<Dual>(int, bool);

template <class Real>
TetrahedralLattice<Real>::TetrahedralLattice(const glm::ivec3& res, int n)
    : resolution(res), coefficients(n) {
  width = (res.x + kRowPadding - 1) / kRowPadding * kRowPadding;
  plane = std::size_t(width) * (res.y + 2) * (res.z + 2);
  const std::size_t values = 3 * std::size_t(n) * kCodes * plane;
  current.assign(values, Real(0));
  next.assign(values, Real(0));
  sum.assign(values, Real(0));
}

template <class Real>
std::size_t TetrahedralLattice<Real>::at(int channel, int i, int code, const glm::ivec3& c) const {
  return (std::size_t(channel * coefficients + i) * kCodes + code) * plane +
         (std::size_t(c.z + 1) * (resolution.y + 2) + (c.y + 1)) * width + c.x;
}

template struct TetrahedralLattice<float>;
template struct TetrahedralLattice<double>;
template struct TetrahedralLattice<Dual>;  // derivatives (framework/math/dual.h)

#include "variants/propagation/tetrahedral_occlusion_body.h"

template TetrahedralOcclusion<float> makeTetrahedralOcclusion<float>(
    const TetrahedralLattice<float>&, const float*);
template TetrahedralOcclusion<double> makeTetrahedralOcclusion<double>(
    const TetrahedralLattice<double>&, const float*);

template <class Real>
void tetrahedralSplitCpu(const Real* cubes, TetrahedralLattice<Real>& lattice) {
  const glm::ivec3 res = lattice.resolution;
  const int n = lattice.coefficients, cubeCells = shared::cellCount(res);
  std::fill(lattice.sum.begin(), lattice.sum.end(), Real(0));
  forEachCell(res, [&](int code, const glm::ivec3& cube) {
    const glm::ivec3 upper = cube + shared::tetUnitOffset(shared::tetAxis(code));
    const int lowerIndex = shared::cellIndex(cube, res), upperIndex = shared::cellIndex(upper, res);
    const Real lowerWeight = Real(shared::tetSplitWeight(cube, res));
    const Real upperWeight = Real(shared::tetSplitWeight(upper, res));
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < n; ++k)
        lattice.current[lattice.at(channel, k, code, cube)] =
            lowerWeight * cubes[shared::coefficientIndex(channel, k, n, lowerIndex, cubeCells)] +
            upperWeight * cubes[shared::coefficientIndex(channel, k, n, upperIndex, cubeCells)];
  });
}

template void tetrahedralSplitCpu<float>(const float*, TetrahedralLattice<float>&);
template void tetrahedralSplitCpu<double>(const double*, TetrahedralLattice<double>&);
template void tetrahedralSplitCpu<Dual>(const Dual*, TetrahedralLattice<Dual>&);

template <class Real>
void tetrahedralMergeCpu(const TetrahedralLattice<Real>& lattice, Real* current,
                         Real* accumulated) {
  const glm::ivec3 res = lattice.resolution;
  const int n = lattice.coefficients, cubeCells = shared::cellCount(res);
  const Real merge = Real(shared::TET_MERGE_WEIGHT);
  const Real step = Real(shared::TET_STEP_LENGTH * shared::TET_MERGE_WEIGHT);
  tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
    for (int z = r.begin(); z < r.end(); ++z)
      for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
          const glm::ivec3 cube(x, y, z);
          const int index = shared::cellIndex(cube, res);
          // The cube's cells (of its 24: the 12 it is the lower cube of and the 12 it is the
          // upper), found once: where coefficient 0 of channel 0 lies; coefficient k of
          // `channel` lies (channel n + k) coefficient strides further.
          std::size_t cells[2 * kCodes];
          int count = 0;
          for (int code = 0; code < kCodes; ++code)
            for (int side = 0; side < 2; ++side) {
              const glm::ivec3 lower = cube - side * shared::tetUnitOffset(shared::tetAxis(code));
              if (shared::tetInside(glm::ivec4(lower, code), res))
                cells[count++] = lattice.at(0, 0, code, lower);
            }
          for (int channel = 0; channel < 3; ++channel)
            for (int k = 0; k < n; ++k) {
              const std::size_t offset = std::size_t(channel * n + k) * kCodes * lattice.plane;
              Real last = 0, sum = 0;
              for (int c = 0; c < count; ++c) {
                last += lattice.current[cells[c] + offset];
                sum += lattice.sum[cells[c] + offset];
              }
              const std::size_t i =
                  std::size_t(shared::coefficientIndex(channel, k, n, index, cubeCells));
              current[i] = merge * last;
              accumulated[i] += step * sum;
            }
        }
  });
}

template void tetrahedralMergeCpu<float>(const TetrahedralLattice<float>&, float*, float*);
template void tetrahedralMergeCpu<double>(const TetrahedralLattice<double>&, double*, double*);
template void tetrahedralMergeCpu<Dual>(const TetrahedralLattice<Dual>&, Dual*, Dual*);

namespace {

using cpu_rows::copyShortRun;
using cpu_rows::loadRegister;
using cpu_rows::RegisterOf;
using cpu_rows::select;
using cpu_rows::storeRegister;

// One register of cells of one code along a row, one channel: from the four neighbour rows
// (from[j], coefficient i at from[j][i * stride[j] + p]) through the three far faces each, the
// fluxes summed per face k, then the four lobes added into out[i * width + p].
template <int N, int Bytes, bool Occluded, class Real>
[[gnu::always_inline]] inline void stepRegister(const TetrahedralTable<Real>& table, int code,
                                                const Real* const (&from)[kFaces],
                                                const std::size_t (&stride)[kFaces], int p,
                                                const Real* t, std::size_t tStride, int width,
                                                Real* out) {
  using V = typename RegisterOf<Real, Bytes>::type;
  V flux[kFaces] = {};
#pragma GCC unroll 4
  for (int j = 0; j < kFaces; ++j) {
    V s[N];
#pragma GCC unroll 16
    for (int i = 0; i < N; ++i) s[i] = loadRegister<V>(from[j] + i * stride[j] + p);
#pragma GCC unroll 4
    for (int k = 0; k < kFaces; ++k) {
      if (k == j) continue;
      const Real* w = table.weight[code][j][k];
      if constexpr (Occluded) {
        V integral = {};
#pragma GCC unroll 16
        for (int i = 0; i < N; ++i) integral += s[i] * w[i];
        const V zero = {};
        const V transmittance = loadRegister<V>(t + tetrahedralFaceSlot(j, k) * tStride + p);
        flux[k] += transmittance * select(integral > zero, integral, zero);
      } else {
        V total = flux[k];
#pragma GCC unroll 16
        for (int i = 0; i < N; ++i) total += s[i] * w[i];
        flux[k] = select(total > flux[k], total, flux[k]);  // flux + max(0, integral)
      }
    }
  }
#pragma GCC unroll 16
  for (int i = 0; i < N; ++i) {
    V value = {};
#pragma GCC unroll 4
    for (int k = 0; k < kFaces; ++k) value += flux[k] * table.lobe[code][k][i];
    storeRegister(out + i * width + p, value);
  }
}

// A row's `count` values written as `accumulation` says: target = value, and the sum gets the
// value (Target), nothing (Deferred) or the value and the previous step's deferred one, this
// step's source at the same cell (SourceAndTarget). Distinct buffers, in loops the compiler must
// be told to vectorise (at -O2 it would not, and the scalar loop was a third of the step).
template <class Real>
[[gnu::always_inline]] inline void storeRow(const Real* __restrict value, Real* __restrict target,
                                            Real* __restrict sum, const Real* __restrict previous,
                                            int count, StepAccumulation accumulation) {
  if (accumulation == StepAccumulation::Deferred) {
#pragma omp simd
    for (int x = 0; x < count; ++x) target[x] = value[x];
  } else if (accumulation == StepAccumulation::Target) {
#pragma omp simd
    for (int x = 0; x < count; ++x) {
      target[x] = value[x];
      sum[x] += value[x];
    }
  } else {
#pragma omp simd
    for (int x = 0; x < count; ++x) {
      target[x] = value[x];
      sum[x] += value[x] + previous[x];
    }
  }
}

// The rows of tasks [begin, end) (task = code * rows + row, row = y + res.y z), every channel.
// A neighbour row at the same x (offset 0) is read where it lies (its cells past the row's end
// are zeros); one a cube along x is staged, shifted, with a zero where the shift leaves the grid.
// Neighbour rows outside the grid along y or z are the layout's zero border rows.
template <int N, int Bytes, class Real>
void stepRows(const TetrahedralTable<Real>& table, TetrahedralLattice<Real>& lattice,
              const TetrahedralOcclusion<Real>* occlusion, StepAccumulation accumulation, int begin,
              int end) {
  const glm::ivec3 res = lattice.resolution;
  const int rows = res.y * res.z, width = lattice.width;
  const std::size_t coefficientStride = std::size_t(kCodes) * lattice.plane;
  std::vector<Real> out(static_cast<std::size_t>(N) * width);
  std::vector<Real> stage(static_cast<std::size_t>(kFaces) * N * width, Real(0));
  for (int task = begin; task < end; ++task) {
    const int code = task / rows, row = task % rows, y = row % res.y, z = row / res.y;
    const glm::ivec3 upper = glm::ivec3(0, y, z) + shared::tetUnitOffset(shared::tetAxis(code));
    if (upper.y >= res.y || upper.z >= res.z) continue;  // no cell of this code in the row
    // Cells x in [0, count) exist (a cell of axis x needs the cube at x + 1).
    const int count = res.x - (shared::tetAxis(code) == 0 ? 1 : 0);
    if (count <= 0) continue;
    const std::size_t rowStart = lattice.at(0, 0, code, glm::ivec3(0, y, z)) -
                                 std::size_t(code) * lattice.plane;  // within a plane
    for (int channel = 0; channel < 3; ++channel) {
      const Real* from[kFaces];
      std::size_t stride[kFaces];
      for (int j = 0; j < kFaces; ++j) {
        const glm::ivec3 o = table.neighbourOffset[code][j];
        const Real* neighbourRow =
            lattice.current.data() +
            lattice.at(channel, 0, table.neighbourCode[code][j], glm::ivec3(0, y + o.y, z + o.z));
        if (o.x == 0) {
          from[j] = neighbourRow;
          stride[j] = coefficientStride;
          continue;
        }
        // Staged cell x is the neighbour row's x + o.x where that lies in the row, else zero.
        Real* staged = stage.data() + std::size_t(j) * N * width;
        const int first = std::max(0, -o.x), last = std::min(res.x, res.x - o.x);  // [first, last)
        for (int i = 0; i < N; ++i) {
          Real* to = staged + std::size_t(i) * width;
          const Real* in = neighbourRow + i * coefficientStride + o.x;
          to[0] = to[res.x - 1] = Real(0);  // the cell the shift leaves empty (else overwritten)
          copyShortRun(in + first, to + first, last - first);
        }
        from[j] = staged;
        stride[j] = std::size_t(width);
      }
      const Real* t = occlusion ? occlusion->transmittance.data() +
                                      std::size_t(code) * 12 * lattice.plane + rowStart
                                : nullptr;
      for (int p = 0; p < width; p += RegisterOf<Real, Bytes>::kLanes) {
        if (occlusion)
          stepRegister<N, Bytes, true>(table, code, from, stride, p, t, lattice.plane, width,
                                       out.data());
        else
          stepRegister<N, Bytes, false>(table, code, from, stride, p, t, lattice.plane, width,
                                        out.data());
      }
      for (int i = 0; i < N; ++i) {
        const std::size_t at = lattice.at(channel, i, code, glm::ivec3(0, y, z));
        storeRow(out.data() + std::size_t(i) * width, lattice.next.data() + at,
                 lattice.sum.data() + at, lattice.current.data() + at, count, accumulation);
      }
    }
  }
}

template <int N, class Real>
void stepRowsAtLevel(CpuKernelLevel level, const TetrahedralTable<Real>& table,
                     TetrahedralLattice<Real>& lattice, const TetrahedralOcclusion<Real>* occlusion,
                     StepAccumulation accumulation, int begin, int end) {
  // Each register width compiled for its own level only; double (the tests' reference precision,
  // never a run's) for x86-64 alone.
  const auto x86_64 = [&] {
    runAtFixedLevel<CpuKernelLevel::X86_64>(
        [&] { stepRows<N, 16>(table, lattice, occlusion, accumulation, begin, end); });
  };
  if constexpr (std::is_same_v<Real, double>) {
    return x86_64();
  } else {
    switch (level) {
      case CpuKernelLevel::X86_64_V4:
        return runAtFixedLevel<CpuKernelLevel::X86_64_V4>(
            [&] { stepRows<N, 64>(table, lattice, occlusion, accumulation, begin, end); });
      case CpuKernelLevel::X86_64_V3:
        return runAtFixedLevel<CpuKernelLevel::X86_64_V3>(
            [&] { stepRows<N, 32>(table, lattice, occlusion, accumulation, begin, end); });
      case CpuKernelLevel::X86_64:
        return x86_64();
    }
  }
}

}  // namespace

template <class Real>
void tetrahedralStepCpu(const TetrahedralTable<Real>& table, TetrahedralLattice<Real>& lattice,
                        const TetrahedralOcclusion<Real>* occlusion, CpuKernelLevel level,
                        StepAccumulation accumulation, int threads) {
  if (table.coefficients != lattice.coefficients)
    throw Error("tetrahedral propagation (CPU): the table's SH order is not the lattice's");
  if (occlusion && occlusion->resolution != lattice.resolution)
    throw Error(
        "tetrahedral propagation (CPU): the geometry volume's faces were made for another grid");
  const glm::ivec3 res = lattice.resolution;
  const int tasks = kCodes * res.y * res.z;
  const auto work = [&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tasks), [&](const tbb::blocked_range<int>& r) {
      if (table.coefficients == 4)
        stepRowsAtLevel<4>(level, table, lattice, occlusion, accumulation, r.begin(), r.end());
      else if (table.coefficients == 9)
        stepRowsAtLevel<9>(level, table, lattice, occlusion, accumulation, r.begin(), r.end());
      else
        stepRowsAtLevel<16>(level, table, lattice, occlusion, accumulation, r.begin(), r.end());
    });
  };
  if (threads > 0) {
    tbb::task_arena arena(threads);
    arena.execute(work);
  } else {
    work();
  }
  lattice.current.swap(lattice.next);
}

template void tetrahedralStepCpu<float>(const TetrahedralTable<float>&, TetrahedralLattice<float>&,
                                        const TetrahedralOcclusion<float>*, CpuKernelLevel,
                                        StepAccumulation, int);
template void tetrahedralStepCpu<double>(const TetrahedralTable<double>&,
                                         TetrahedralLattice<double>&,
                                         const TetrahedralOcclusion<double>*, CpuKernelLevel,
                                         StepAccumulation, int);
template void tetrahedralStepCpu<Dual>(const TetrahedralTable<Dual>&, TetrahedralLattice<Dual>&,
                                       const TetrahedralOcclusion<Dual>*, CpuKernelLevel,
                                       StepAccumulation, int);

}  // namespace lpvlab
