#pragma once
// Cosine-weighted directions about a normal: the importance sampling of a Lambertian BRDF, for
// which BRDF * cos / pdf = albedo exactly.

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace lpvlab {

// cos and sin of an angle in [-pi/4, pi/4] by their Taylor polynomials, within 3e-7: all that
// the concentric map below needs, at a fraction of std::sin and std::cos's cost.
inline glm::vec2 cosSinQuarter(float angle) {
  const float a2 = angle * angle;
  const float cosine =
      1.0f + a2 * (-1.0f / 2 + a2 * (1.0f / 24 + a2 * (-1.0f / 720 + a2 * (1.0f / 40320))));
  const float sine = angle * (1.0f + a2 * (-1.0f / 6 + a2 * (1.0f / 120 + a2 * (-1.0f / 5040))));
  return {cosine, sine};
}

// An orthonormal basis (tangent, bitangent) about unit n, without branches or a division by a
// small number (Duff et al., "Building an Orthonormal Basis, Revisited", 2017).
inline void orthonormalBasis(const glm::vec3& n, glm::vec3& tangent, glm::vec3& bitangent) {
  const float sign = std::copysign(1.0f, n.z);
  const float c = -1.0f / (sign + n.z);
  const float d = n.x * n.y * c;
  tangent = glm::vec3(1.0f + sign * n.x * n.x * c, sign * d, -sign * n.x);
  bitangent = glm::vec3(d, sign + n.y * n.y * c, -n.y);
}

// A unit direction with density cos(theta) / pi (1/sr) about unit normal n, from two uniform
// numbers: a uniform point on the unit disk by Shirley and Chiu's concentric map (square rings to
// disk rings, so stratified numbers stay stratified) lifted onto the hemisphere (Malley's method).
inline glm::vec3 cosineHemisphere(const glm::vec3& n, float u1, float u2) {
  const float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
  glm::vec2 disk(0.0f);
  if (std::abs(a) > std::abs(b)) {
    disk = a * cosSinQuarter(float(M_PI / 4) * (b / a));
  } else if (b != 0.0f) {
    const glm::vec2 cs = cosSinQuarter(float(M_PI / 4) * (a / b));
    disk = b * glm::vec2(cs.y, cs.x);  // angle pi/2 - the quarter angle
  }
  glm::vec3 tangent, bitangent;
  orthonormalBasis(n, tangent, bitangent);
  const float height = std::sqrt(std::max(0.0f, 1.0f - glm::dot(disk, disk)));
  return disk.x * tangent + disk.y * bitangent + height * n;
}

// The power heuristic (beta = 2) weight of a sample drawn with density `chosen` when the other
// strategy would have drawn it with density `other` (Veach 1997, 9.2.4).
inline float powerHeuristic(float chosen, float other) {
  const float c2 = chosen * chosen;
  return c2 / (c2 + other * other);
}

}  // namespace lpvlab
