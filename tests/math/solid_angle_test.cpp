// Face solid angles of standard propagation, derived in code, against closed forms, the tiling
// identity and direct numerical integration of dOmega = cos(theta) / r^2 dA.

#include <gtest/gtest.h>

#include <cmath>

#include "framework/math/solid_angle.h"

namespace lpvlab {
namespace {

// Midpoint rule over a planar rectangle: origin-facing solid angle of the face
// {p = corner + s * u + t * v, s, t in [0, 1]} with unit normal n.
double integrateFace(glm::dvec3 corner, glm::dvec3 u, glm::dvec3 v, int n) {
  const glm::dvec3 normal = glm::normalize(glm::cross(u, v));
  const double area = glm::length(glm::cross(u, v)) / (double(n) * n);
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const glm::dvec3 p = corner + (i + 0.5) / n * u + (j + 0.5) / n * v;
      const double r = glm::length(p);
      sum += std::abs(glm::dot(normal, p)) / (r * r * r) * area;
    }
  return sum;
}

TEST(FaceSolidAngles, FarFaceMatchesClosedForm) {
  EXPECT_NEAR(cubeFaceSolidAngles().farFace, 4.0 * std::asin(0.1), 1e-14);
  EXPECT_NEAR(cubeFaceSolidAngles().farFace, 0.4006696846, 1e-10);
}

TEST(FaceSolidAngles, SideFaceFillsTheSharedFaceWithTheFarFace) {
  const auto angles = cubeFaceSolidAngles();
  const double sharedFace = 2.0 * M_PI / 3.0;  // a unit square at distance 1/2: 4 asin(1/2)
  EXPECT_NEAR(angles.farFace + 4.0 * angles.sideFace, sharedFace, 1e-13);
  EXPECT_NEAR(angles.sideFace, 0.4234313544, 1e-10);
  // The widely copied constant 0.4234413544 is a typo, off by 1e-5: tell them apart.
  EXPECT_GT(std::abs(angles.sideFace - 0.4234413544), 5e-6);
}

TEST(FaceSolidAngles, ThirtyFacesTileTheSphere) {
  const auto angles = cubeFaceSolidAngles();
  EXPECT_NEAR(6.0 * (angles.farFace + 4.0 * angles.sideFace), 4.0 * M_PI, 1e-12);
}

TEST(FaceSolidAngles, AgreeWithNumericalIntegration) {
  const auto angles = cubeFaceSolidAngles();
  EXPECT_NEAR(integrateFace({-0.5, -0.5, 1.5}, {1, 0, 0}, {0, 1, 0}, 1000), angles.farFace, 1e-6);
  EXPECT_NEAR(integrateFace({0.5, -0.5, 0.5}, {0, 1, 0}, {0, 0, 1}, 1000), angles.sideFace, 1e-6);
}

TEST(TriangleSolidAngle, OctantIsOneEighthOfTheSphere) {
  EXPECT_NEAR(triangleSolidAngle({1, 0, 0}, {0, 1, 0}, {0, 0, 1}), M_PI / 2.0, 1e-14);
  // Wider than a hemisphere's quarter: the atan2 branch.
  EXPECT_NEAR(quadSolidAngle({-1e3, -1e3, 1}, {1e3, -1e3, 1}, {1e3, 1e3, 1}, {-1e3, 1e3, 1}),
              2.0 * M_PI, 1e-2);
}

}  // namespace
}  // namespace lpvlab
