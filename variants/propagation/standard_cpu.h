#pragma once
// Standard propagation by gathering, on the CPU (the CPU backend, strategy.h): the transfer of
// shaders/propagation/standard_gather.comp at SH orders 1-3, with or without the geometry volume
// and its bounces, generic in its scalar type (float for speed, double for the tests).
//
// One source of the mathematics: every number the kernel multiplies by comes from the shared
// GLSL compiled as C++ (standard_faces.glsl: face directions, normals and solid angles;
// sh.glsl: the SH basis and the clamped-cosine lobe), tabulated once per run in StandardFaceTable.
// What the kernel adds is the loop order and three factorings, exact but for float rounding:
//   - every face a cell receives light through has one of six normals (the axes), so the
//     target's coefficients are sum over normals n of (the fluxes through faces with normal n) *
//     lobe(n) / pi: six lobes per cell instead of thirty;
//   - a face direction has non-zero components only along the flow axis and the face's normal,
//     so the SH basis functions needing the third axis vanish there (and on the axis lobes); the
//     kernel skips those products, knowing which when it is compiled, and the table builder checks
//     that each skipped value is exactly zero in the shared GLSL;
//   - a face's flux is added as f = max(f + intensity, f) = f + max(intensity, 0).
// A row of cells along x is done a vector register at a time (GCC vector types, the register
// width of the instruction set), all six neighbours per cell, so each target cell is written
// once. Rows are padded to a multiple of 16 cells, the grid's edges are zero rows (a zero source
// sends nothing), and the two x neighbours are the row itself staged shifted by a cell, so every
// cell goes through the same vector code with no edge tests. The grid layout is the GL kernels'
// (shaders/common/grid.glsl), so buffers move between the backends unchanged.
//
// Instruction sets: the row loop is compiled three times, for x86-64 (SSE2, any 64-bit x86),
// x86-64-v3 (AVX2 and FMA) and x86-64-v4 (AVX-512), and the widest this CPU has runs ("auto"),
// or the one named, so one binary is correct and fast from the oldest to the newest machine and
// a machine with AVX-512 can test the narrower versions too.
//
// The geometry volume does not change during a frame's propagation, so what it does to each face
// is found once per frame (StandardOcclusion, from the shared GLSL in double precision): per
// target cell and face the transmittance T where the face's direction crosses the shared face
// (geometry_volume_lookup.glsl's gvBlockingAt, gvTransmittance), by which the kernel multiplies
// the face's flux; and, with bounces, per cell and outgoing face whose T < 1, the surfaces' albedo
// times the blocked fraction and their lobe (gvMeanAlbedo, gvSurfaceNormal, shCosineLobeAt).
// Bounces are sparse (only faces at surfaces block), so they are a list per row, added to the
// row's cells after its vector pass.
//
// Scattering (standardScatterCpu) sends each cell's light to one neighbour direction at a time:
// six passes over the grid, each adding into the target what every cell sends that way (within a
// pass each target receives from exactly one source, so no atomics), then the accumulated grid
// once. It does scattering's extra work and traffic (six lobe sums and six read-modify-writes of
// the target per cell, where gathering does one of each) and gives the same grid as gathering.
//
// Threads: rows are shared out by oneTBB. Each target cell is written by exactly one task, in a
// fixed order of additions, so the result does not depend on the thread count (no atomics).

#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "variants/propagation/step_accumulation.h"

namespace lpvlab {

// Directions and normals are both indexed by axis and sign: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z.
// Per neighbour (its offset from the target cell, `direction`) and face normal: the SH basis at
// the direction to that face's centre times the face's solid angle, so that the face's flux is
// max(0, sum_k source_k scaledBasis_k) (standard_faces.glsl's standardFaceFlux without a GV).
// The face whose normal is the offset itself is the one the two cells share, which receives
// nothing: its row is zero and the kernel skips it. Per normal: the coefficients a unit flux
// through a face with that normal adds to the target, its clamped-cosine lobe over pi.
template <class Real>
struct StandardFaceTable {
  static constexpr int kDirections = 6, kMaxCoefficients = 16;
  int coefficients = 4;  // (order + 1)^2
  glm::ivec3 offset[kDirections];  // the neighbour's offset; light flows from it, along -offset
  Real scaledBasis[kDirections][kDirections][kMaxCoefficients];  // [direction][normal][k]
  Real normalLobe[kDirections][kMaxCoefficients];                // [normal][k]
};

// What the geometry volume does to the faces of a frame's propagation (see above).
template <class Real>
struct StandardOcclusion {
  static constexpr int kFaces = 30;  // per target cell: 6 neighbours x 5 faces
  glm::ivec3 resolution{0};
  int width = 0;  // cells per row as the kernel pads rows
  // transmittance[(face * rows + row) * width + x], face = standardFaceSlot(direction, normal),
  // rows = resolution.y * resolution.z; 1 in the padding.
  std::vector<Real> transmittance;
  // A face of a cell's own outgoing transfer that the GV blocks (T < 1), with bounces.
  struct Bounce {
    int x;                 // the cell in its row
    int direction, normal; // the table's entry for the face (light flowing along -offset)
    Real weight[3];        // per channel: mean albedo times (1 - T)
  };
  std::vector<Bounce> bounces;           // by row, then x
  std::vector<std::size_t> firstBounce;  // row r's bounces: [firstBounce[r], firstBounce[r + 1])
  std::vector<Real> bounceLobes;         // per bounce, `coefficients` values: lobe(n) / pi
  int coefficients = 4;
};

// A second reprojection of each cell's received light, from an iteration on (directed
// propagation, directed_cpu.h): where a cell reprojects, its target coefficients are
//     (sum over normals n of the fluxes through its faces with normal n times faceWeight[n]) *
//     lobe[k]
// in place of sum_n flux_n normalLobe[n][k]. Laid out as StandardOcclusion's transmittance (rows
// padded to `width` cells).
template <class Real>
struct ReprojectedCells {
  static constexpr int kMaxLobeCoefficients = 9;  // a clamped cosine has no band 3
  glm::ivec3 resolution{0};
  int width = 0;
  int coefficients = 4;
  // since[row * width + x]: the first iteration in which the cell reprojects, or kNever.
  static constexpr Real kNever = Real(1 << 24);
  std::vector<Real> since;
  std::vector<Real> faceWeight;  // [(normal * rows + row) * width + x]
  std::vector<Real> lobe;        // [(k * rows + row) * width + x], k < min(coefficients, 9)
};

// Light in two grids (directed propagation's release, directed_faces.glsl): "attached" light,
// which the reprojecting cells (ReprojectedCells) re-emit about their normal, and "free" light,
// which propagates as standard. Before each iteration a cell that does not keep its attached
// light moves it into the free grid; cell c (grid.glsl's cellIndex) keeps it in the iterations
// keepFrom[c] <= i < keepUntil[c].
struct ReleasedCells {
  static constexpr int kAlways = 1 << 30;  // a keepUntil past every iteration
  std::vector<int> keepFrom, keepUntil;
  bool keeps(std::size_t cell, int iteration) const {
    return keepFrom[cell] <= iteration && iteration < keepUntil[cell];
  }
};

// The cells per row of the kernel's padded rows (StandardOcclusion, ReprojectedCells).
int standardCpuRowWidth(int cellsPerRow);

// The slot of the face with `normal` receiving light from neighbour `direction` (normal !=
// direction): 0..29.
constexpr int standardFaceSlot(int direction, int normal) {
  return direction * 5 + (normal < direction ? normal : normal - 1);
}

// Throws an Error for an SH order outside 1..3 or a negative or non-finite solid angle. `Angle`:
// double, or Dual with Real = Dual (the table's derivatives with respect to the solid angles):
// makeStandardFaceTable<Dual, Dual>.
template <class Real, class Angle = double>
StandardFaceTable<Real> makeStandardFaceTable(int shOrder,
                                              std::type_identity_t<Angle> farSolidAngle,
                                              std::type_identity_t<Angle> sideSolidAngle);

// What a GV (geometry_volume.h's layout, on the GV's cells: one more than `resolution` per axis)
// does to the faces of a grid of `resolution`; with `gvAlbedo` (its (rho A, A) per GV cell) also
// the bounces. `table` gives the faces' solid angles and basis. `GvValue`: float, or Dual with
// Real = Dual (a GV with derivatives: the faces' transmittances and bounces get them).
template <class Real, class GvValue = float>
StandardOcclusion<Real> makeStandardOcclusion(const StandardFaceTable<Real>& table,
                                              const glm::ivec3& resolution,
                                              const GvValue* gvBlocking,
                                              std::type_identity_t<const GvValue*> gvAlbedo);

// The multiply-adds the kernel does per cell-iteration and channel with `coefficients` per
// channel: the face products it does not skip plus the lobes' (each face's max and add not
// counted).
int standardGatherMultiplyAdds(int coefficients);
// The same for scattering, whose six passes each add the lobes.
int standardScatterMultiplyAdds(int coefficients);

// The CPU instruction sets the kernel is compiled for, narrowest first.
const std::vector<std::string>& cpuKernelInstructionSets();
// Those this CPU can run.
std::vector<std::string> supportedCpuKernelInstructionSets();

// One gathering iteration: target = what every cell receives from its six neighbours' `source`,
// accumulated += target. Grids in grid.glsl's layout (3 channels x coefficients x cells).
// `occlusion`: the GV's faces, made for this table and resolution, or null (no GV, or an
// iteration before the GV's first occluded one). `accumulation`: see StepAccumulation
// (step_accumulation.h). `isa`: "auto" or one of cpuKernelInstructionSets(); throws an Error for
// an unknown one or one this CPU lacks. `threads`: 0 for oneTBB's default (all cores).
// `reprojected`: the cells that reproject their light in this iteration (`iteration`), or null.
template <class Real>
void standardGatherCpu(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
                       const Real* source, Real* target, Real* accumulated,
                       const std::string& isa = "auto", int threads = 0,
                       const StandardOcclusion<Real>* occlusion = nullptr,
                       StepAccumulation accumulation = StepAccumulation::Target,
                       const ReprojectedCells<Real>* reprojected = nullptr, int iteration = 0);

// The same iteration by scattering (see above): the same result, scattering's work.
template <class Real>
void standardScatterCpu(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
                        const Real* source, Real* target, Real* accumulated,
                        const std::string& isa = "auto", int threads = 0,
                        const StandardOcclusion<Real>* occlusion = nullptr,
                        StepAccumulation accumulation = StepAccumulation::Target);

// One iteration by scattering or gathering, as `scatter` says.
template <class Real>
void standardIterationCpu(bool scatter, const StandardFaceTable<Real>& table,
                          const glm::ivec3& resolution, const Real* source, Real* target,
                          Real* accumulated, const std::string& isa = "auto", int threads = 0,
                          std::type_identity_t<const StandardOcclusion<Real>*> occlusion = nullptr,
                          StepAccumulation accumulation = StepAccumulation::Target) {
  if (scatter)
    standardScatterCpu(table, resolution, source, target, accumulated, isa, threads, occlusion,
                       accumulation);
  else
    standardGatherCpu(table, resolution, source, target, accumulated, isa, threads, occlusion,
                      accumulation);
}

}  // namespace lpvlab
