#include "framework/math/solid_angle.h"

#include <cmath>

namespace lpvlab {

double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
  const double denominator =
      la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  // atan2 keeps the result right when the denominator is negative (triangles over pi/2 wide).
  return 2.0 * std::atan2(numerator, denominator);
}

double quadSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                      const glm::dvec3& d) {
  return triangleSolidAngle(a, b, c) + triangleSolidAngle(a, c, d);
}

CubeFaceSolidAngles cubeFaceSolidAngles() {
  CubeFaceSolidAngles out{};
  out.farFace = quadSolidAngle({-0.5, -0.5, 1.5}, {0.5, -0.5, 1.5}, {0.5, 0.5, 1.5},
                               {-0.5, 0.5, 1.5});
  out.sideFace = quadSolidAngle({0.5, -0.5, 0.5}, {0.5, 0.5, 0.5}, {0.5, 0.5, 1.5},
                                {0.5, -0.5, 1.5});
  return out;
}

}  // namespace lpvlab
