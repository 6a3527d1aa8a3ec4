#include "framework/math/tetrahedral_face_integrals.h"

#include <array>
#include <cmath>

#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using glm::dvec3;
using Coefficients = std::array<double, shared::SH_MAX_COEFFICIENTS>;

constexpr int kSubdivisions = 5;  // 4^5 = 1024 sub-triangles per face

// Radon's 7-point degree-5 rule on a triangle: barycentric points and weights (summing to 1).
struct RadonPoint {
  double a, b, c, weight;
};
std::array<RadonPoint, 7> radonRule() {
  const double s = std::sqrt(15.0);
  const double a1 = (9.0 - 2.0 * s) / 21.0, b1 = (6.0 + s) / 21.0, w1 = (155.0 + s) / 1200.0;
  const double a2 = (9.0 + 2.0 * s) / 21.0, b2 = (6.0 - s) / 21.0, w2 = (155.0 - s) / 1200.0;
  return {{{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, 9.0 / 40.0},
           {a1, b1, b1, w1}, {b1, a1, b1, w1}, {b1, b1, a1, w1},
           {a2, b2, b2, w2}, {b2, a2, b2, w2}, {b2, b2, a2, w2}}};
}

// Adds the integral of Y_i over the triangle (p, q, r) seen from the origin, whose plane lies at
// `distance` from it, subdividing `depth` more times.
void integrate(const dvec3& p, const dvec3& q, const dvec3& r, double distance, int depth,
               Coefficients& out) {
  if (depth > 0) {
    const dvec3 pq = 0.5 * (p + q), qr = 0.5 * (q + r), rp = 0.5 * (r + p);
    integrate(p, pq, rp, distance, depth - 1, out);
    integrate(pq, q, qr, distance, depth - 1, out);
    integrate(rp, qr, r, distance, depth - 1, out);
    integrate(pq, qr, rp, distance, depth - 1, out);
    return;
  }
  static const std::array<RadonPoint, 7> rule = radonRule();
  const double area = 0.5 * glm::length(glm::cross(q - p, r - p));
  for (const RadonPoint& point : rule) {
    const dvec3 x = point.a * p + point.b * q + point.c * r;
    const double length = glm::length(x);
    const double weight = point.weight * area * distance / (length * length * length);
    for (int i = 0; i < shared::SH_MAX_COEFFICIENTS; ++i)
      out[i] += weight * shared::shBasisAt(i, x / length);
  }
}

std::vector<double> computeFaceIntegrals() {
  std::vector<double> table(std::size_t(shared::TET_FACE_INTEGRAL_COUNT), 0.0);
  for (int code = 0; code < shared::TET_PER_CUBE; ++code)
    for (int sharedFace = 0; sharedFace < shared::TET_FACES; ++sharedFace) {
      // The neighbour's centroid relative to this cell's: the cell mirrored in face j.
      const dvec3 source = (0.25 * shared::TET_SQRT2) * shared::tetFaceNormal(code, sharedFace);
      for (int face = 0; face < shared::TET_FACES; ++face) {
        if (face == sharedFace) continue;
        std::array<dvec3, 3> corner;
        int n = 0;
        for (int v = 0; v < 4; ++v)
          if (v != shared::tetOppositeVertex(face))
            corner[n++] = shared::tetVertexFromCentroid(code, v) - source;
        const double distance = glm::dot(corner[0], shared::tetFaceNormal(code, face));
        Coefficients integral{};
        integrate(corner[0], corner[1], corner[2], distance, kSubdivisions, integral);
        for (int i = 0; i < shared::SH_MAX_COEFFICIENTS; ++i)
          table[std::size_t(shared::tetFaceIntegralIndex(code, sharedFace, face, i))] = integral[i];
      }
    }
  return table;
}

}  // namespace

const std::vector<double>& tetrahedralFaceIntegrals() {
  static const std::vector<double> table = computeFaceIntegrals();
  return table;
}

}  // namespace lpvlab
