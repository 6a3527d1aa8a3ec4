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
  void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
};

}  // namespace lpvlab
