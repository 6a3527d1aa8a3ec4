#include "framework/metrics/flip_color.h"

#include <cmath>

namespace lpvlab::flip {

namespace {

// glm matrices are column-major: each inner triple here is a column.
const glm::dmat3 kRgbToXyz(10135552.0 / 24577794.0, 2613072.0 / 12288897.0,
                           1425312.0 / 73733382.0,  // column R
                           8788810.0 / 24577794.0, 8788810.0 / 12288897.0,
                           8788810.0 / 73733382.0,  // column G
                           4435075.0 / 24577794.0, 887015.0 / 12288897.0,
                           70074185.0 / 73733382.0);  // column B
const glm::dmat3 kXyzToRgb = glm::inverse(kRgbToXyz);
// (0.950428545, 1, 1.088900371): FLIP's D65 reference illuminant.
const glm::dvec3 kWhite = kRgbToXyz * glm::dvec3(1.0);

constexpr double kDelta = 6.0 / 29.0;

double labF(double t) {
  return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

}  // namespace

glm::dvec3 linearRgbToXyz(const glm::dvec3& rgb) { return kRgbToXyz * rgb; }

glm::dvec3 xyzToLinearRgb(const glm::dvec3& xyz) { return kXyzToRgb * xyz; }

glm::dvec3 xyzToYCxCz(const glm::dvec3& xyz) {
  const glm::dvec3 n = xyz / kWhite;
  return {116.0 * n.y - 16.0, 500.0 * (n.x - n.y), 200.0 * (n.y - n.z)};
}

glm::dvec3 yCxCzToXyz(const glm::dvec3& ycxcz) {
  const double y = (ycxcz.x + 16.0) / 116.0;
  return glm::dvec3(y + ycxcz.y / 500.0, y, y - ycxcz.z / 200.0) * kWhite;
}

glm::dvec3 xyzToLab(const glm::dvec3& xyz) {
  const glm::dvec3 n = xyz / kWhite;
  const double fx = labF(n.x), fy = labF(n.y), fz = labF(n.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

glm::dvec3 huntAdjust(const glm::dvec3& lab) {
  return {lab.x, 0.01 * lab.x * lab.y, 0.01 * lab.x * lab.z};
}

double hyab(const glm::dvec3& a, const glm::dvec3& b) {
  return std::abs(a.x - b.x) + std::hypot(a.y - b.y, a.z - b.z);
}

}  // namespace lpvlab::flip
