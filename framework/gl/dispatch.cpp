#include "framework/gl/dispatch.h"

#include <glad/gl.h>

namespace lpvlab {

void dispatchCovering(const glm::ivec3& domain, const glm::ivec3& groupSize, unsigned barriers) {
  const glm::ivec3 groups = (domain + groupSize - 1) / groupSize;
  if (groups.x > 0 && groups.y > 0 && groups.z > 0)
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
  glMemoryBarrier(barriers);
}

}  // namespace lpvlab
