// The SH integrals over the far faces of tetrahedral propagation
// (framework/math/tetrahedral_face_integrals.h) against independent ground truths:
//   - band 0: Y_0 times the face's exact solid angle (Van Oosterom and Strackee);
//   - band 1: Arvo's closed form for the integral of w over a spherical triangle,
//     1/2 sum over edges of the edge's arc angle times the unit normal of its great circle;
//   - every band: the 12 far faces of a cell's four neighbours tile the sphere, so their
//     integrals are the sphere's, 2 sqrt(pi) for Y_0 and 0 for every other Y_i;
//   - bands 2-3: a direct sum over 10^6 Fibonacci directions classified by the face they pass
//     through (1e-3: the discretisation of the faces' edges).

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "framework/math/shared.h"
#include "framework/math/solid_angle.h"
#include "framework/math/tetrahedral_face_integrals.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using glm::dvec3;
using Triangle = std::array<dvec3, 3>;

double integralOf(int code, int sharedFace, int face, int i) {
  return tetrahedralFaceIntegrals()[std::size_t(shared::tetFaceIntegralIndex(code, sharedFace, face, i))];
}

// Face k of cell `code` as seen from the centroid of its neighbour across face j, ordered
// counter-clockwise seen from outside the unit sphere about that centroid.
Triangle farFace(int code, int sharedFace, int face) {
  const dvec3 source = (0.25 * shared::TET_SQRT2) * shared::tetFaceNormal(code, sharedFace);
  Triangle t;
  int n = 0;
  for (int v = 0; v < 4; ++v)
    if (v != shared::tetOppositeVertex(face)) t[n++] = shared::tetVertexFromCentroid(code, v) - source;
  if (glm::dot(glm::cross(t[1] - t[0], t[2] - t[0]), t[0]) < 0.0) std::swap(t[1], t[2]);
  return t;
}

// Arvo 1995: the integral of w over the spherical triangle (counter-clockwise from outside).
dvec3 arvoVectorIntegral(const Triangle& t) {
  dvec3 sum{0.0};
  for (int e = 0; e < 3; ++e) {
    const dvec3 a = glm::normalize(t[e]), b = glm::normalize(t[(e + 1) % 3]);
    sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::normalize(glm::cross(a, b));
  }
  return 0.5 * sum;
}

template <typename F>
void forEachFarFace(F f) {
  for (int code = 0; code < shared::TET_PER_CUBE; ++code)
    for (int j = 0; j < shared::TET_FACES; ++j)
      for (int k = 0; k < shared::TET_FACES; ++k)
        if (k != j) f(code, j, k);
}

TEST(TetrahedralFaceIntegrals, BandZeroIsTheSolidAngle) {
  forEachFarFace([](int code, int j, int k) {
    const Triangle t = farFace(code, j, k);
    EXPECT_NEAR(integralOf(code, j, k, 0), shared::SH_Y0 * triangleSolidAngle(t[0], t[1], t[2]), 1e-10);
  });
}

TEST(TetrahedralFaceIntegrals, BandOneMatchesArvosClosedForm) {
  forEachFarFace([](int code, int j, int k) {
    const dvec3 vector = arvoVectorIntegral(farFace(code, j, k));
    ASSERT_GT(glm::length(vector), 0.1);
    for (int i = 1; i < 4; ++i)  // band 1 is linear in w: Y_i(v) = |v| Y_i(v / |v|)
      EXPECT_NEAR(integralOf(code, j, k, i),
                  glm::length(vector) * shared::shBasisAt(i, glm::normalize(vector)), 1e-10)
          << "code " << code << " j " << j << " k " << k << " i " << i;
  });
}

TEST(TetrahedralFaceIntegrals, TheTwelveFarFacesIntegrateTheSphere) {
  const glm::ivec4 origin{0, 0, 0, 0};
  for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
    const glm::ivec4 source{origin.x, origin.y, origin.z, code};
    for (int i = 0; i < shared::SH_MAX_COEFFICIENTS; ++i) {
      double sum = 0.0;
      for (int face = 0; face < shared::TET_FACES; ++face) {
        const glm::ivec4 target = shared::tetNeighbour(source, face);
        int back = -1;
        for (int k = 0; k < shared::TET_FACES; ++k)
          if (shared::tetNeighbour(target, k) == source) back = k;
        ASSERT_GE(back, 0);
        for (int k = 0; k < shared::TET_FACES; ++k)
          if (k != back) sum += integralOf(target.w, back, k, i);
      }
      EXPECT_NEAR(sum, i == 0 ? 2.0 * std::sqrt(M_PI) : 0.0, 1e-9) << "code " << code << " Y_" << i;
    }
  }
}

TEST(TetrahedralFaceIntegrals, HigherBandsMatchADirectSumOverTheSphere) {
  const int code = 7, j = 2;  // one view; the other orientations are its rotations
  std::array<Triangle, shared::TET_FACES> faces;
  std::array<std::array<double, shared::SH_MAX_COEFFICIENTS>, shared::TET_FACES> sum{};
  for (int k = 0; k < shared::TET_FACES; ++k)
    if (k != j) faces[k] = farFace(code, j, k);
  const int n = 1000000;
  for (int s = 0; s < n; ++s) {
    const double z = 1.0 - 2.0 * (s + 0.5) / n, r = std::sqrt(1.0 - z * z);
    const double phi = M_PI * (3.0 - std::sqrt(5.0)) * s;
    const dvec3 w{r * std::cos(phi), r * std::sin(phi), z};
    for (int k = 0; k < shared::TET_FACES; ++k) {
      if (k == j) continue;
      const Triangle& t = faces[k];
      bool inside = true;
      for (int e = 0; e < 3; ++e) inside = inside && glm::dot(w, glm::cross(t[e], t[(e + 1) % 3])) >= 0.0;
      if (!inside) continue;
      for (int i = 0; i < shared::SH_MAX_COEFFICIENTS; ++i) sum[k][i] += shared::shBasisAt(i, w) * 4.0 * M_PI / n;
    }
  }
  for (int k = 0; k < shared::TET_FACES; ++k) {
    if (k == j) continue;
    for (int i = 4; i < shared::SH_MAX_COEFFICIENTS; ++i)
      EXPECT_NEAR(integralOf(code, j, k, i), sum[k][i], 1e-3) << "k " << k << " Y_" << i;
  }
}

}  // namespace
}  // namespace lpvlab
