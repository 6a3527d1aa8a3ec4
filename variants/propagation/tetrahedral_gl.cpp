#include "variants/propagation/tetrahedral_gl.h"

#include <utility>
#include <vector>

#include "framework/gl/dispatch.h"
#include "framework/math/shared.h"
#include "framework/math/tetrahedral_face_integrals.h"
#include "framework/math/tetrahedral_solid_angles.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {
namespace split_kernel {
#include "shaders/propagation/tetrahedral_split_interface.glsl"
}
namespace gather_kernel {
#include "shaders/propagation/tetrahedral_gather_interface.glsl"
}
namespace merge_kernel {
#include "shaders/propagation/tetrahedral_merge_interface.glsl"
}
}  // namespace

TetrahedralGlWork tetrahedralGlWork(const TetrahedralGlSettings& settings) {
  const double n = settings.coefficients, cells = double(kTetrahedralCellsPerCube);
  TetrahedralGlWork w;
  w.step.multiplyAdds = cells * 3 * 12 * 2 * n;
  w.step.bytes = cells * 4 * (4 * 3 * n + 3 * n + 2 * 3 * n);
  if (settings.withGv) {
    w.step.multiplyAdds += cells * 12 * 8 * 4;
    w.step.bytes += cells * 12 * 8 * 16;
  }
  w.frame = {2 * 24 * 3 * n * 2, 4 * 24 * 3 * n * 3};
  return w;
}

TetrahedralGlKernel::TetrahedralGlKernel(ShaderCompiler& shaders,
                                         const TetrahedralGlSettings& settings,
                                         const glm::ivec3& resolution)
    : settings_(settings) {
  const TetrahedralFaceSolidAngles angles = tetrahedralFaceSolidAngles();
  const int coefficients = settings.coefficients;
  split_ = shaders.compute("propagation/tetrahedral_split.comp", {SpecConstant::i(0, coefficients)});
  gather_ = shaders.compute("propagation/tetrahedral_gather.comp",
                            {SpecConstant::f(0, float(angles.smallFace)),
                             SpecConstant::f(1, float(angles.largeFace)),
                             SpecConstant::i(2, coefficients), SpecConstant::b(3, settings.withGv),
                             SpecConstant::b(4, settings.faceIntegrals)});
  if (settings.faceIntegrals) {
    const std::vector<double>& table = tetrahedralFaceIntegrals();
    const std::vector<float> values(table.begin(), table.end());
    faceIntegralTable_ = gl::Buffer(values.size() * sizeof(float), "tetrahedral face integrals",
                                    values.data());
  }
  merge_ = shaders.compute("propagation/tetrahedral_merge.comp", {SpecConstant::i(0, coefficients)});
  // The lattice holds 12 cells per cube, each with the light grid's coefficients.
  const std::size_t bytes = std::size_t(kTetrahedralCellsPerCube) * 3 * coefficients *
                            resolution.x * resolution.y * resolution.z * sizeof(float);
  current_ = gl::Buffer(bytes, "tetrahedral lattice (current)");
  scratch_ = gl::Buffer(bytes, "tetrahedral lattice (propagation scratch)");
  sum_ = gl::Buffer(bytes, "tetrahedral lattice (sum of steps)");
}

void TetrahedralGlKernel::propagate(const glm::ivec3& res, int iterations, DualBuffer& current,
                                    DualBuffer& accumulated, const gl::Buffer* gv,
                                    int firstOccludedIteration) {
  const glm::ivec3 cellDomain{kTetrahedralCellsPerCube * res.x, res.y, res.z};
  {
    using namespace split_kernel;
    split_.use();
    glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
    current.bindStorage(BUFFER_CUBES);
    current_.bindStorage(BUFFER_CELLS);
    dispatchCovering(cellDomain, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                     GL_SHADER_STORAGE_BARRIER_BIT);
  }
  {
    using namespace gather_kernel;
    sum_.zero();
    gather_.use();
    glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
    sum_.bindStorage(BUFFER_SUM);
    // Without a GV the kernel was compiled without its reads, and the uniform doesn't exist.
    if (settings_.withGv) gv->bindStorage(BUFFER_GEOMETRY_VOLUME);
    if (settings_.faceIntegrals) faceIntegralTable_.bindStorage(BUFFER_FACE_INTEGRALS);
    const int firstOccluded = shared::tetFirstOccludedStep(firstOccludedIteration);
    for (int i = 0; i < iterations; ++i) {
      if (settings_.withGv) glUniform1i(LOCATION_OCCLUDED_STEP, i >= firstOccluded);
      current_.bindStorage(BUFFER_SOURCE);
      scratch_.bindStorage(BUFFER_TARGET);
      dispatchCovering(cellDomain, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                       GL_SHADER_STORAGE_BARRIER_BIT);
      std::swap(current_, scratch_);
    }
  }
  using namespace merge_kernel;
  merge_.use();
  glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
  current_.bindStorage(BUFFER_LAST);
  sum_.bindStorage(BUFFER_SUM);
  current.bindStorage(BUFFER_CURRENT);
  accumulated.bindStorage(BUFFER_ACCUMULATED);
  dispatchCovering(res, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z}, GL_SHADER_STORAGE_BARRIER_BIT);
}

std::size_t TetrahedralGlKernel::memoryBytes() const {
  return current_.size() + scratch_.size() + sum_.size() + faceIntegralTable_.size();
}

}  // namespace lpvlab
