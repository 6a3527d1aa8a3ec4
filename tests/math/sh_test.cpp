// The order-1 SH functions of shaders/common/sh.glsl (compiled as C++ in double precision)
// against numerical integration over the sphere.

#include <gtest/gtest.h>

#include "framework/math/shared.h"
#include "math/sphere_quadrature.h"

namespace lpvlab {
namespace {

using glm::dvec3;
using testing::integrateSphere;

double basis(int i, const dvec3& w) { return shared::shBasis(w)[i]; }

TEST(SphericalHarmonics, ConstantsMatchThesisEquation42) {
  EXPECT_NEAR(shared::SH_Y0, 0.2820947918, 1e-10);
  EXPECT_NEAR(shared::SH_Y1, 0.4886025119, 1e-10);
  const dvec3 w = glm::normalize(dvec3(0.3, -0.5, 0.8));
  EXPECT_DOUBLE_EQ(basis(1, w), -shared::SH_Y1 * w.y);
  EXPECT_DOUBLE_EQ(basis(2, w), shared::SH_Y1 * w.z);
  EXPECT_DOUBLE_EQ(basis(3, w), -shared::SH_Y1 * w.x);
}

TEST(SphericalHarmonics, BasisIsOrthonormal) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double integral =
          integrateSphere([&](const dvec3& w) { return basis(i, w) * basis(j, w); }, 16, 32);
      EXPECT_NEAR(integral, i == j ? 1.0 : 0.0, 1e-12) << "<Y" << i << ", Y" << j << ">";
    }
}

TEST(SphericalHarmonics, CosineLobeIsTheProjectionOfTheClampedCosine) {
  // Closed forms of eq. 4.3 first.
  EXPECT_NEAR(shared::shZonalCosine(0), std::sqrt(M_PI) / 2.0, 1e-15);
  EXPECT_NEAR(shared::shZonalCosine(1), std::sqrt(M_PI / 3.0), 1e-15);
  const dvec3 normals[] = {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}, glm::normalize(dvec3(1, 2, -3)),
                           glm::normalize(dvec3(-0.2, 0.9, 0.4))};
  for (const dvec3& n : normals) {
    const glm::dvec4 lobe = shared::shCosineLobe(n);
    for (int i = 0; i < 4; ++i) {
      const double projected = integrateSphere(
          [&](const dvec3& w) { return std::max(0.0, glm::dot(n, w)) * basis(i, w); }, 400, 800);
      EXPECT_NEAR(lobe[i], projected, 2e-5) << "coefficient " << i;
    }
  }
}

TEST(SphericalHarmonics, IntegralOfALambertianVplIsItsFlux) {
  // Eq. 4.1: I(w) = Phi / pi * max(0, n.w) carries flux Phi; shIntegral must agree.
  const double flux = 3.7;
  const glm::dvec4 c = (flux / M_PI) * shared::shCosineLobe(glm::normalize(dvec3(1, 1, 0)));
  EXPECT_NEAR(shared::shIntegral(c), flux, 1e-12);
  const double numeric =
      integrateSphere([&](const dvec3& w) { return shared::shEvaluate(c, w); }, 16, 32);
  EXPECT_NEAR(numeric, flux, 1e-12);
}

}  // namespace
}  // namespace lpvlab
