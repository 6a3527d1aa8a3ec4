#pragma once
// The paraboloid map of a VPL's hemisphere (Brabec, Annen and Seidel 2002; the imperfect shadow
// maps of Ritschel et al. 2008 use it): a unit direction d with local coordinates (x, y, z) about
// the VPL's normal (z >= 0) maps to the disk point uv = (x, y) / (1 + z), |uv| <= 1, and back by
// d = (2u, 2v, 1 - u^2 - v^2) / (1 + u^2 + v^2). A square map of `size` texels per side covers
// [-1, 1]^2; texels whose centre lies outside the unit disk see nothing. A texel near the centre
// subtends about (2 / size)^2 sr, near the rim a quarter of that.

#include <cmath>

#include <glm/glm.hpp>

#include "framework/reference/hemisphere_sampling.h"

namespace lpvlab {

class ParaboloidFrame {
public:
  // About unit normal n (hemisphere_sampling.h's branch-free basis).
  explicit ParaboloidFrame(const glm::vec3& n) : n_(n) { orthonormalBasis(n, t_, b_); }

  // The disk point of unit direction d; false when d is below the hemisphere (z <= 0).
  bool project(const glm::vec3& d, glm::vec2& uv) const {
    const float z = glm::dot(d, n_);
    if (!(z > 0.0f)) return false;
    uv = glm::vec2(glm::dot(d, t_), glm::dot(d, b_)) / (1.0f + z);
    return true;
  }

  // The unit direction of disk point uv (|uv| <= 1).
  glm::vec3 direction(const glm::vec2& uv) const {
    const float r2 = glm::dot(uv, uv);
    return (2.0f * uv.x * t_ + 2.0f * uv.y * b_ + (1.0f - r2) * n_) / (1.0f + r2);
  }

private:
  glm::vec3 n_, t_, b_;
};

// The texel (column, row) of disk point uv in a size x size map, clamped to the map.
inline glm::ivec2 paraboloidTexel(const glm::vec2& uv, int size) {
  const glm::vec2 t = (uv * 0.5f + 0.5f) * float(size);
  return glm::clamp(glm::ivec2(glm::floor(t)), glm::ivec2(0), glm::ivec2(size - 1));
}

// The disk point of a texel's centre.
inline glm::vec2 paraboloidTexelCentre(int column, int row, int size) {
  return (glm::vec2(float(column), float(row)) + 0.5f) / float(size) * 2.0f - 1.0f;
}

}  // namespace lpvlab
