// Dual (framework/math/dual.h) against ceres::Jet, the forward-mode AD of Ceres Solver: every
// operation and function, on values and derivatives with respect to four parameters, at random
// points; the chain rule through a composite expression; and GLM's vectors of Dual (the shared
// GLSL's dot, length, normalize, clamp, floor) against the same written with Jets.

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "framework/math/dual.h"

namespace lpvlab {
namespace {

using Jet = ceres::Jet<double, kDualSlots>;

static_assert(std::is_trivially_copyable_v<Dual> && std::is_trivially_default_constructible_v<Dual>,
              "GLM's unions need a trivial type");

// A point and its derivatives, the same in both types.
struct Pair {
  Dual d;
  Jet j;
};

Pair randomPair(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> value(lo, hi), slope(-2.0, 2.0);
  Pair p;
  p.d = Dual(value(rng));
  p.j = Jet(p.d.a);
  for (int k = 0; k < kDualSlots; ++k) p.j.v[k] = p.d.v[k] = slope(rng);
  return p;
}

void expectSame(const Dual& d, const Jet& j, const std::string& what) {
  const double scale = std::max(1.0, std::abs(j.a));
  EXPECT_NEAR(d.a, j.a, 1e-13 * scale) << what;
  for (int k = 0; k < kDualSlots; ++k)
    EXPECT_NEAR(d.v[k], j.v[k], 1e-12 * std::max(1.0, std::abs(j.v[k]))) << what << " slot " << k;
}

TEST(Dual, ArithmeticAndFunctionsAreCeresJets) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Pair x = randomPair(rng, 0.1, 3.0), y = randomPair(rng, -3.0, 3.0);
    const double s = std::uniform_real_distribution<double>(-2.0, 2.0)(rng);
    expectSame(x.d + y.d, x.j + y.j, "x + y");
    expectSame(x.d - y.d, x.j - y.j, "x - y");
    expectSame(x.d * y.d, x.j * y.j, "x * y");
    expectSame(y.d / x.d, y.j / x.j, "y / x");
    expectSame(-y.d, -y.j, "-y");
    expectSame(x.d * s, x.j * s, "x * s");
    expectSame(s * x.d, s * x.j, "s * x");
    expectSame(x.d / s, x.j / s, "x / s");
    expectSame(s - x.d, s - x.j, "s - x");
    expectSame(sqrt(x.d), ceres::sqrt(x.j), "sqrt");
    expectSame(inversesqrt(x.d), 1.0 / ceres::sqrt(x.j), "inversesqrt");
    expectSame(exp(y.d), ceres::exp(y.j), "exp");
    expectSame(log(x.d), ceres::log(x.j), "log");
    expectSame(pow(x.d, y.d), ceres::pow(x.j, y.j), "pow");
    expectSame(abs(y.d), ceres::abs(y.j), "abs");
    expectSame(floor(y.d), ceres::floor(y.j), "floor");
    expectSame(ceil(y.d), ceres::ceil(y.j), "ceil");
    expectSame(max(x.d, y.d), ceres::fmax(x.j, y.j), "max");
    expectSame(min(x.d, y.d), ceres::fmin(x.j, y.j), "min");
    EXPECT_EQ(x.d < y.d, x.j < y.j);
    EXPECT_EQ(x.d >= y.d, x.j >= y.j);
    // A composite: the chain rule through several steps.
    const Dual d = exp(-x.d * y.d) * sqrt(x.d + y.d * y.d) / (1.0 + abs(y.d));
    const Jet j = ceres::exp(-x.j * y.j) * ceres::sqrt(x.j + y.j * y.j) / (1.0 + ceres::abs(y.j));
    expectSame(d, j, "composite");
  }
}

TEST(Dual, ClampTakesTheDerivativeOfTheBranchTaken) {
  const Dual inside = Dual::parameter(0.5, 0), below = Dual::parameter(-0.5, 1),
             above = Dual::parameter(1.5, 2);
  EXPECT_EQ(clamp(inside, Dual(0.0), Dual(1.0)).v[0], 1.0);
  EXPECT_EQ(clamp(below, Dual(0.0), Dual(1.0)).v[1], 0.0);
  EXPECT_EQ(clamp(above, Dual(0.0), Dual(1.0)).v[2], 0.0);
  EXPECT_EQ(clamp(above, Dual(0.0), Dual(1.0)).a, 1.0);
}

TEST(Dual, GlmVectorsOfDualAreJetArithmetic) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    Pair p[3];
    for (Pair& c : p) c = randomPair(rng, -2.0, 2.0);
    const glm::vec<3, Dual> v(p[0].d, p[1].d, p[2].d);
    const Jet lengthJet = ceres::sqrt(p[0].j * p[0].j + p[1].j * p[1].j + p[2].j * p[2].j);
    expectSame(glm::dot(v, v), lengthJet * lengthJet, "dot");
    expectSame(glm::length(v), lengthJet, "length");
    const glm::vec<3, Dual> n = glm::normalize(v);
    for (int c = 0; c < 3; ++c) expectSame(n[c], p[c].j / lengthJet, "normalize");
    const glm::vec<3, Dual> shifted = v - 0.5, clamped = clamp(v, Dual(-1.0), Dual(1.0)),
                            floored = floor(v);
    for (int c = 0; c < 3; ++c) {
      expectSame(shifted[c], p[c].j - 0.5, "v - 0.5");
      expectSame(clamped[c], ceres::fmin(ceres::fmax(p[c].j, Jet(-1.0)), Jet(1.0)), "clamp");
      expectSame(floored[c], ceres::floor(p[c].j), "floor");
    }
  }
}

TEST(Dual, NonFiniteValuesOrDerivativesAreSeen) {
  EXPECT_TRUE(isfinite(Dual::parameter(1.0, 0)));
  EXPECT_FALSE(isfinite(Dual(std::nan(""))));
  EXPECT_FALSE(isfinite(sqrt(Dual::parameter(0.0, 0))));  // d sqrt(x)/dx at 0 is infinite
}

}  // namespace
}  // namespace lpvlab
