#include "variants/propagation/standard_cpu.h"

#include "variants/propagation/standard_cpu_kernels.h"

namespace lpvlab {

template <class Real, class Angle>
StandardFaceTable<Real> makeStandardFaceTable(int shOrder,
                                              std::type_identity_t<Angle> farSolidAngle,
                                              std::type_identity_t<Angle> sideSolidAngle) {
  if (shOrder < 1 || shOrder > 3)
    throw Error("standard propagation (CPU): SH order " + std::to_string(shOrder) +
                " is not 1, 2 or 3");
  for (const Angle& omega : {farSolidAngle, sideSolidAngle})
    if (!(omega >= Angle(0.0)) || !std::isfinite(double(omega)))
      throw Error("standard propagation (CPU): face solid angle " +
                  std::to_string(double(omega)) + " is not a finite non-negative number");
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
      // standardFaceSolidAngle picks one of the two angles, so it is linear in them: as its
      // weights on each, an Angle with derivatives keeps them (1 x + 0 y = x exactly).
      const Angle omega = farSolidAngle * shared::standardFaceSolidAngle(f, 1.0, 0.0) +
                          sideSolidAngle * shared::standardFaceSolidAngle(f, 0.0, 1.0);
      for (int k = 0; k < table.coefficients; ++k)
        table.scaledBasis[direction][normal][k] = Real(omega * shared::shBasisAt(k, w));
    }
  }
  // What the kernel skips must be exactly zero (see requiredAxes).
  for (int direction = 0; direction < kDirections; ++direction)
    for (int normal = 0; normal < kDirections; ++normal)
      for (int k = 0; k < table.coefficients; ++k)
        if ((!faceUsesBasis(direction, normal, k) && table.scaledBasis[direction][normal][k] != Real(0)) ||
            (!lobeUsesBasis(normal, k) && table.normalLobe[normal][k] != Real(0)))
          throw Error("standard propagation (CPU): SH coefficient " + std::to_string(k) +
                      " is not zero where the kernel skips it (sh.glsl or standard_faces.glsl "
                      "changed? see requiredAxes)");
  return table;
}

template StandardFaceTable<float> makeStandardFaceTable<float>(int, double, double);
template StandardFaceTable<double> makeStandardFaceTable<double>(int, double, double);
template StandardFaceTable<Dual> makeStandardFaceTable<Dual, Dual>(int, Dual, Dual);

int standardCpuRowWidth(int cellsPerRow) {
  return (cellsPerRow + kRowPadding - 1) / kRowPadding * kRowPadding;
}

#include "variants/propagation/standard_occlusion_body.h"

template StandardOcclusion<float> makeStandardOcclusion<float>(const StandardFaceTable<float>&,
                                                               const glm::ivec3&, const float*,
                                                               const float*);
template StandardOcclusion<double> makeStandardOcclusion<double>(const StandardFaceTable<double>&,
                                                                 const glm::ivec3&, const float*,
                                                                 const float*);

namespace {

// The face products the kernel does per cell-iteration and channel, and the lobes' per pass.
int faceMultiplyAdds(int coefficients) {
  int count = 0;
  for (int normal = 0; normal < 6; ++normal)
    for (int k = 0; k < coefficients; ++k)
      for (int direction = 0; direction < 6; ++direction)
        count += faceUsesBasis(direction, normal, k) ? 1 : 0;
  return count;
}

int lobeMultiplyAdds(int coefficients) {
  int count = 0;
  for (int normal = 0; normal < 6; ++normal)
    for (int k = 0; k < coefficients; ++k) count += lobeUsesBasis(normal, k) ? 1 : 0;
  return count;
}

}  // namespace

int standardGatherMultiplyAdds(int coefficients) {
  return faceMultiplyAdds(coefficients) + lobeMultiplyAdds(coefficients);
}

int standardScatterMultiplyAdds(int coefficients) {
  return faceMultiplyAdds(coefficients) + 6 * lobeMultiplyAdds(coefficients);
}

const std::vector<std::string>& cpuKernelInstructionSets() {
  static const std::vector<std::string> sets = {cpuKernelLevelName(CpuKernelLevel::X86_64),
                                                cpuKernelLevelName(CpuKernelLevel::X86_64_V3),
                                                cpuKernelLevelName(CpuKernelLevel::X86_64_V4)};
  return sets;
}

std::vector<std::string> supportedCpuKernelInstructionSets() {
  return namesThisCpuRuns(cpuKernelInstructionSets(), cpuRunsKernel);
}

template void standardScatterCpu<float>(const StandardFaceTable<float>&, const glm::ivec3&,
                                        const float*, float*, float*, const std::string&, int,
                                        const StandardOcclusion<float>*, StepAccumulation);
template void standardGatherCpu<float>(const StandardFaceTable<float>&, const glm::ivec3&,
                                       const float*, float*, float*, const std::string&, int,
                                       const StandardOcclusion<float>*, StepAccumulation,
                                       const ReprojectedCells<float>*, int);

}  // namespace lpvlab
