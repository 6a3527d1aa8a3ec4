#pragma once
// An axis-aligned bounding box in world space (metres).

#include <limits>

#include <glm/glm.hpp>

namespace lpvlab {

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};
  bool empty() const { return min.x > max.x; }
  glm::vec3 extent() const { return max - min; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  // Corner i (0..7) of the box: bit 0 picks max.x over min.x, bit 1 y, bit 2 z.
  glm::vec3 corner(int i) const {
    return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
  }
  void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
};

}  // namespace lpvlab
