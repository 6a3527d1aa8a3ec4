#include "framework/math/tetrahedral_solid_angles.h"

#include "framework/math/solid_angle.h"

namespace lpvlab {

TetrahedralFaceSolidAngles tetrahedralFaceSolidAngles() {
  const glm::dvec3 p{-0.5, -0.25, 0.0}, q{0.5, -0.25, 0.0}, rPlus{0.0, 0.25, 0.5},
      rMinus{0.0, 0.25, -0.5};
  const glm::dvec3 source{0.0, -0.25, 0.25};
  TetrahedralFaceSolidAngles out{};
  out.smallFace = triangleSolidAngle(p - source, q - source, rMinus - source);
  out.largeFace = triangleSolidAngle(p - source, rPlus - source, rMinus - source);
  out.sharedFace = triangleSolidAngle(p, q, rPlus);
  return out;
}

}  // namespace lpvlab
