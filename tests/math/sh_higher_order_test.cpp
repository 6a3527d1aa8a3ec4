// The SH of shaders/common/sh.glsl to order 3 (16 coefficients; compiled as C++ in double
// precision) against numerical integration over the sphere (sphere_quadrature.h):
//   - the 16 basis functions are orthonormal;
//   - the zonal cosine coefficients z_0..z_3 are 2 pi integral_0^1 Y_l0(t) t dt, and the clamped
//     cosine lobes of orders 2 and 3 are the projections of max(0, n . w) for random n;
//   - rotation: with M_ij = integral Y_i(R w) Y_j(w) dw, M is block diagonal by band, each block
//     orthogonal, and projecting a rotated band-limited function is rotating its projection.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "framework/math/shared.h"
#include "math/sphere_quadrature.h"

namespace lpvlab {
namespace {

using glm::dvec3;
using testing::integrateSphere;
constexpr int kCount = 16;  // order 3

double basis(int i, const dvec3& w) { return shared::shBasisAt(i, w); }

dvec3 randomUnit(std::mt19937& random) {
  std::normal_distribution<double> normal;
  return glm::normalize(dvec3(normal(random), normal(random), normal(random)));
}

// A random rotation (Gram-Schmidt of random vectors; columns, determinant +1).
glm::dmat3 randomRotation(std::mt19937& random) {
  const dvec3 a = randomUnit(random), b0 = randomUnit(random);
  const dvec3 b = glm::normalize(b0 - glm::dot(b0, a) * a);
  return glm::dmat3(a, b, glm::cross(a, b));
}

TEST(HigherOrderSh, BandsAndCountsOfTheIndexing) {
  EXPECT_EQ(shared::shCoefficientCount(1), 4);
  EXPECT_EQ(shared::shCoefficientCount(2), 9);
  EXPECT_EQ(shared::shCoefficientCount(3), 16);
  for (int i = 0; i < kCount; ++i) {
    const int l = shared::shBand(i);
    EXPECT_GE(i, l * l) << i;
    EXPECT_LT(i, (l + 1) * (l + 1)) << i;
  }
}

TEST(HigherOrderSh, SixteenBasisFunctionsAreOrthonormal) {
  // Products of two band-3 functions have degree 6: 8 Gauss nodes and 16 in phi are exact.
  for (int i = 0; i < kCount; ++i)
    for (int j = 0; j < kCount; ++j) {
      const double integral =
          integrateSphere([&](const dvec3& w) { return basis(i, w) * basis(j, w); }, 8, 16);
      EXPECT_NEAR(integral, i == j ? 1.0 : 0.0, 1e-12) << "<Y" << i << ", Y" << j << ">";
    }
}

TEST(HigherOrderSh, ZonalCosineCoefficientsAreTheIntegralsOfTheClampedCosine) {
  std::vector<double> t, w;
  testing::gaussLegendre(16, t, w);
  const int zonal[4] = {0, 2, 6, 12};  // index of Y_l0: l (l + 1)
  for (int l = 0; l <= 3; ++l) {
    double integral = 0.0;  // 2 pi integral_0^1 Y_l0(t) t dt, Gauss on [0, 1]
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double u = 0.5 * (t[k] + 1.0);
      integral += 0.5 * w[k] * 2.0 * M_PI * basis(zonal[l], dvec3(std::sqrt(1.0 - u * u), 0.0, u)) * u;
    }
    EXPECT_NEAR(shared::shZonalCosine(l), integral, 1e-13) << "z_" << l;
  }
  EXPECT_NEAR(shared::shZonalCosine(2), std::sqrt(5.0 * M_PI) / 8.0, 1e-15);
  EXPECT_EQ(shared::shZonalCosine(3), 0.0);
}

TEST(HigherOrderSh, CosineLobesOfOrdersTwoAndThreeAreProjectionsOfTheClampedCosine) {
  std::mt19937 random(2024);
  for (int trial = 0; trial < 4; ++trial) {
    const dvec3 n = randomUnit(random);
    for (int i = 0; i < kCount; ++i) {
      const double projected = integrateSphere(
          [&](const dvec3& w) { return std::max(0.0, glm::dot(n, w)) * basis(i, w); }, 300, 600);
      EXPECT_NEAR(shared::shCosineLobeAt(i, n), projected, 3e-5)
          << "coefficient " << i << " (band " << shared::shBand(i) << ")";
    }
  }
}

// M_ij = integral Y_i(R w) Y_j(w) dw over all 16 x 16 pairs.
std::vector<double> rotationMatrix(const glm::dmat3& r) {
  std::vector<double> m(kCount * kCount);
  for (int i = 0; i < kCount; ++i)
    for (int j = 0; j < kCount; ++j)
      m[i * kCount + j] =
          integrateSphere([&](const dvec3& w) { return basis(i, r * w) * basis(j, w); }, 8, 16);
  return m;
}

TEST(HigherOrderSh, RotationMatricesAreBlockDiagonalAndOrthogonal) {
  std::mt19937 random(77);
  for (int trial = 0; trial < 3; ++trial) {
    const std::vector<double> m = rotationMatrix(randomRotation(random));
    for (int i = 0; i < kCount; ++i)
      for (int j = 0; j < kCount; ++j) {
        if (shared::shBand(i) != shared::shBand(j)) {
          EXPECT_NEAR(m[i * kCount + j], 0.0, 1e-12) << "bands do not mix: " << i << "," << j;
          continue;
        }
        double mmT = 0.0;  // (M M^T)_ij within the band
        for (int k = 0; k < kCount; ++k) mmT += m[i * kCount + k] * m[j * kCount + k];
        EXPECT_NEAR(mmT, i == j ? 1.0 : 0.0, 1e-12) << i << "," << j;
      }
  }
}

TEST(HigherOrderSh, ProjectingARotatedFunctionIsRotatingItsProjection) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 3; ++trial) {
    const glm::dmat3 r = randomRotation(random);
    const std::vector<double> m = rotationMatrix(r);
    std::vector<double> c(kCount);
    for (double& v : c) v = uniform(random);
    auto f = [&](const dvec3& w) {
      double sum = 0.0;
      for (int j = 0; j < kCount; ++j) sum += c[j] * basis(j, w);
      return sum;
    };
    const glm::dmat3 rInverse = glm::transpose(r);
    for (int i = 0; i < kCount; ++i) {
      // g(w) = f(R^T w): f rotated by R.
      const double projected =
          integrateSphere([&](const dvec3& w) { return f(rInverse * w) * basis(i, w); }, 8, 16);
      double rotated = 0.0;
      for (int j = 0; j < kCount; ++j) rotated += m[i * kCount + j] * c[j];
      EXPECT_NEAR(projected, rotated, 1e-12) << "coefficient " << i;
    }
    // The cosine lobe about n, rotated, is the lobe about R n (band by band, to order 3).
    const dvec3 n = randomUnit(random);
    for (int i = 0; i < kCount; ++i) {
      double rotated = 0.0;
      for (int j = 0; j < kCount; ++j) rotated += m[i * kCount + j] * shared::shCosineLobeAt(j, n);
      EXPECT_NEAR(shared::shCosineLobeAt(i, r * n), rotated, 1e-12) << "coefficient " << i;
    }
  }
}

}  // namespace
}  // namespace lpvlab
