#include "framework/pipeline/cascade.h"

#include <algorithm>
#include <vector>

#include "framework/core/error.h"
#include "framework/gl/dispatch.h"
#include "framework/math/cascade_placement.h"
#include "framework/math/shared.h"
#include "framework/pipeline/cascade_blend.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/host_readback.h"

// restrict.glsl over a host copy of the child grid (the CPU carry).
LPVLAB_SHARED_GLSL_BEGIN
struct RestrictKernel {
  const float* child;
  real childCoefficient(int index) { return real(child[index]); }
#include "shaders/cascade/restrict.glsl"
};
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace restrict_kernel {
#include "shaders/cascade/restrict_interface.glsl"
}

void setCascadeBlendUniforms(const Frame& frame, int level) {
  std::vector<GridGeometry> levels;
  for (const LightGrid& grid : frame.renderedLevels()) levels.push_back(grid.geometry);
  setCascadeBlendUniforms(levels, level, frame.cascadeBlendCells);
}

CascadeCarry::CascadeCarry(ShaderCompiler& shaders, int shOrder, bool onCpu)
    : coefficients_(shared::shCoefficientCount(shOrder)), onCpu_(onCpu) {
  if (!onCpu_)
    program_ = shaders.compute("cascade/restrict.comp", {SpecConstant::i(0, coefficients_)});
}

void CascadeCarry::carry(const LightGrid& child, LightGrid& parent) {
  const glm::ivec3 offset = childOffsetInParentCells(child.geometry, parent.geometry);
  if (onCpu_) return carryOnCpu(child, parent, offset);
  using namespace restrict_kernel;
  program_.use();
  glUniform3iv(LOCATION_RESOLUTION, 1, &parent.geometry.resolution[0]);
  glUniform3iv(LOCATION_CHILD_OFFSET, 1, &offset[0]);
  child.current.bindStorage(BUFFER_CHILD);
  parent.current.bindStorage(BUFFER_PARENT);
  dispatchCovering(parent.geometry.resolution / 2, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                   GL_SHADER_STORAGE_BARRIER_BIT);
}

void CascadeCarry::carryOnCpu(const LightGrid& child, LightGrid& parent, const glm::ivec3& offset) {
  const std::vector<float>& childLight = child.current.hostRead();
  std::vector<float>& parentLight = parent.current.host();
  const glm::ivec3 resolution = parent.geometry.resolution, half = resolution / 2;
  const int cells = shared::cellCount(resolution);
  shared::RestrictKernel kernel{childLight.data()};
  for (int z = 0; z < half.z; ++z)
    for (int y = 0; y < half.y; ++y)
      for (int x = 0; x < half.x; ++x) {
        const glm::ivec3 c(x, y, z);
        const int parentIndex = shared::cellIndex(offset + c, resolution);
        for (int channel = 0; channel < 3; ++channel)
          for (int k = 0; k < coefficients_; ++k)
            parentLight[std::size_t(shared::coefficientIndex(channel, k, coefficients_, parentIndex, cells))] =
                float(kernel.restrictedCoefficient(channel, k, coefficients_, c, resolution));
      }
}

}  // namespace lpvlab
