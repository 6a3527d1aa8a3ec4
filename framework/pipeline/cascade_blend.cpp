#include "framework/pipeline/cascade_blend.h"

#include <string>
#include <vector>

#include <glad/gl.h>

#include "framework/core/error.h"

namespace lpvlab {
namespace {
namespace blend_kernel {
#include "shaders/common/cascade_blend_interface.glsl"
}
}  // namespace

void setCascadeBlendUniforms(std::span<const GridGeometry> levels, int level, float blendCells) {
  using namespace blend_kernel;
  if (levels.size() > std::size_t(CASCADE_MAX_LEVELS))
    throw Error("cascade: at most " + std::to_string(CASCADE_MAX_LEVELS) + " levels can be rendered");
  std::vector<glm::vec4> placement;
  for (const GridGeometry& grid : levels) placement.emplace_back(grid.origin, grid.cellSize);
  glUniform4fv(LOCATION_CASCADE_LEVEL, GLsizei(placement.size()), &placement[0][0]);
  glUniform1i(LOCATION_CASCADE_LEVELS, int(levels.size()));
  glUniform1i(LOCATION_CASCADE_CURRENT, level);
  glUniform1f(LOCATION_CASCADE_BLEND_CELLS, blendCells);
  glUniform3iv(LOCATION_CASCADE_RESOLUTION, 1, &levels[std::size_t(level)].resolution[0]);
}

}  // namespace lpvlab
