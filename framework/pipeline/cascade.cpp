#include "framework/pipeline/cascade.h"

#include <algorithm>
#include <vector>

#include "framework/core/error.h"
#include "framework/gl/dispatch.h"
#include "framework/math/cascade_placement.h"
#include "framework/math/shared.h"
#include "framework/pipeline/frame.h"

namespace lpvlab {

namespace {
constexpr int kMaxLevels = 8;  // CASCADE_MAX_LEVELS in cascade_blend.glsl
}

void setCascadeBlendUniforms(const Frame& frame, int level) {
  const std::span<const LightGrid> levels = frame.renderedLevels();
  if (levels.size() > std::size_t(kMaxLevels))
    throw Error("cascade: at most " + std::to_string(kMaxLevels) + " levels can be rendered");
  std::vector<glm::vec4> placement;
  for (const LightGrid& grid : levels)
    placement.emplace_back(grid.geometry.origin, grid.geometry.cellSize);
  glUniform4fv(40, GLsizei(placement.size()), &placement[0][0]);
  glUniform1i(48, int(levels.size()));
  glUniform1i(49, level);
  glUniform1f(50, frame.cascadeBlendCells);
  glUniform3iv(51, 1, &levels[std::size_t(level)].geometry.resolution[0]);
}

CascadeCarry::CascadeCarry(ShaderCompiler& shaders, int shOrder)
    : program_(shaders.compute("cascade/restrict.comp",
                               {SpecConstant::i(0, shared::shCoefficientCount(shOrder))})) {}

void CascadeCarry::carry(const LightGrid& child, LightGrid& parent) const {
  const glm::ivec3 offset = childOffsetInParentCells(child.geometry, parent.geometry);
  program_.use();
  glUniform3iv(0, 1, &parent.geometry.resolution[0]);
  glUniform3iv(1, 1, &offset[0]);
  child.current.bindStorage(0);
  parent.current.bindStorage(1);
  dispatchCovering(parent.geometry.resolution / 2, glm::ivec3(4), GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace lpvlab
