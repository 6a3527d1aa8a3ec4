#pragma once
// Tetrahedral propagation (tetrahedral.cpp) on the CPU: its three GL kernels' work (split the
// cubic grid onto the lattice, gather steps on the lattice, merge back), generic in the scalar
// type (float for speed, double for the tests).
//
// One source of the mathematics: every number the kernel multiplies by comes from the shared
// GLSL compiled as C++ (tetrahedral_lattice.glsl: neighbours, face directions, normals, solid
// angles, the split and merge weights, the GV crossing; sh.glsl: basis and lobes) or from the
// exact face integrals the GL kernel reads (tetrahedral_face_integrals.h), tabulated once per
// run. What the CPU adds is the loop order and one exact factoring: a cell's twelve far faces
// have four normals (the cell's own faces), so the fluxes are summed per face first and the four
// lobes added once.
//
// The lattice lives on the CPU in a layout of its own, never seen outside the strategy: per
// channel and coefficient, per code (the cell's position in its cube, tetrahedral_lattice.glsl),
// the cubes' values in rows along x, padded to a multiple of 16 cells, with a border of zero rows
// along y and z. For a given code, the neighbour across each face is the same code at the same
// cube offset for every cube, so a row of cells of one code is computed a vector register at a
// time from four neighbour rows, with no edge tests: a neighbour row one cube along x is staged
// shifted, with a zero where the shift leaves the grid, and a neighbour that does not exist (past
// the grid) is a zero cell, which sends nothing, as on GL. Steps are paired as standard
// propagation's are (step_accumulation.h), so the sum is read and written every other step.
//
// The geometry volume does not change during a frame, so the transmittance of every face (12 per
// cell) is found once per GV (TetrahedralOcclusion), from the shared GLSL in double precision.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "framework/core/cpu_dispatch.h"
#include "variants/propagation/step_accumulation.h"

namespace lpvlab {

template <class Real>
struct TetrahedralTable {
  static constexpr int kCodes = 12, kFaces = 4, kMaxCoefficients = 16;
  int coefficients = 4;  // (order + 1)^2
  // Per code and face j: the neighbour across it, as a cube offset and its code.
  glm::ivec3 neighbourOffset[kCodes][kFaces];
  int neighbourCode[kCodes][kFaces];
  // weight[code][j][k][i]: face k's flux from the neighbour across j is max(0, sum_i c_i weight_i)
  // (the face's SH integrals, or its solid angle times the basis towards its centroid); zero for
  // k == j.
  Real weight[kCodes][kFaces][kFaces][kMaxCoefficients];
  Real lobe[kCodes][kFaces][kMaxCoefficients];  // face k's clamped-cosine lobe / pi
};

// `faceIntegrals`: the "integral" face flux (else "centre"). An Error for an SH order outside 1..3.
template <class Real>
TetrahedralTable<Real> makeTetrahedralTable(int shOrder, bool faceIntegrals);

// The lattice of a grid of `resolution` cubes on the CPU (see above): `current` (the last step),
// `next` (its ping-pong partner) and `sum` (of every step).
template <class Real>
struct TetrahedralLattice {
  TetrahedralLattice() = default;
  TetrahedralLattice(const glm::ivec3& resolution, int coefficients);
  glm::ivec3 resolution{0};
  int coefficients = 4;
  int width = 0;          // padded row length (cells)
  std::size_t plane = 0;  // values per (channel, coefficient, code)
  std::vector<Real> current, next, sum;
  // Where cube `cell`'s cell of `code` keeps coefficient i of `channel`.
  std::size_t at(int channel, int i, int code, const glm::ivec3& cell) const;
  std::size_t bytes() const { return (current.size() + next.size() + sum.size()) * sizeof(Real); }
};

// Per lattice cell and far face, the GV's transmittance (1 where it blocks nothing).
template <class Real>
struct TetrahedralOcclusion {
  glm::ivec3 resolution{0};
  // transmittance[(code * 12 + tetrahedralFaceSlot(j, k)) * lattice.plane + row offset + x]
  std::vector<Real> transmittance;
};

// The slot of far face k of the neighbour across face j (k != j): 0..11.
constexpr int tetrahedralFaceSlot(int j, int k) { return j * 3 + (k < j ? k : k - 1); }

// What a GV (geometry_volume.h's layout, on resolution + 1 cells per axis) does to every face.
// `GvValue`: float, or Dual with Real = Dual (a GV with derivatives, framework/math/dual.h).
template <class Real, class GvValue = float>
TetrahedralOcclusion<Real> makeTetrahedralOcclusion(const TetrahedralLattice<Real>& lattice,
                                                    const GvValue* gvBlocking);

// Cubic grid (grid.glsl's layout) -> lattice.current (tetrahedral_split.comp); sum := 0.
template <class Real>
void tetrahedralSplitCpu(const Real* cubes, TetrahedralLattice<Real>& lattice);

// One gather step (tetrahedral_gather.comp): next := what every cell receives from its four
// neighbours in current, added to the sum as `accumulation` says (pairedAccumulation(step,
// steps) for a frame's steps), then current and next swap. `occlusion`: null, or the GV's faces
// for this lattice's grid. `threads`: 0 for oneTBB's default.
template <class Real>
void tetrahedralStepCpu(const TetrahedralTable<Real>& table, TetrahedralLattice<Real>& lattice,
                        const TetrahedralOcclusion<Real>* occlusion, CpuKernelLevel level,
                        StepAccumulation accumulation = StepAccumulation::Target,
                        int threads = 0);

// Lattice -> cubic grids (tetrahedral_merge.comp): current := the last step, merged;
// accumulated += the step-length-weighted sum, merged.
template <class Real>
void tetrahedralMergeCpu(const TetrahedralLattice<Real>& lattice, Real* current, Real* accumulated);

// The multiply-adds a step does per lattice cell and channel (12 face weights and 4 lobes of N).
inline int tetrahedralStepMultiplyAdds(int coefficients) { return 16 * coefficients; }

}  // namespace lpvlab
