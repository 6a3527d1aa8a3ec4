#pragma once
// Forward-mode automatic differentiation: a dual number carries a value and its derivatives with
// respect to kDualSlots parameters, and every operation applies the chain rule, so a kernel
// instantiated with Dual computes its result and the result's exact derivatives in one pass
// (derivatives through whole frames: docs/fitting.md, "Derivatives").
//
// Why not ceres::Jet, which does the same: the CPU kernels run the shared GLSL compiled as C++
// (framework/math/shared.h), which needs its scalar type inside GLM's vectors and converted
// implicitly from a double literal, as GLSL converts (`vec3(0.0)`, `p - 0.5`). GLM's vectors hold
// their components in unions, which need a trivially copyable type, and ceres::Jet is neither
// that (its derivatives are an Eigen vector) nor implicitly constructible from a double. Dual is
// both; the rules are Ceres's (jet.h), and tests/math/dual_test.cpp checks every function here
// against ceres::Jet, value and derivatives.
//
// Comparisons compare values, as Ceres's do: where a kernel branches or clamps, the derivative is
// that of the branch taken (one-sided at the kink, as Ceres's). floor and int conversions have
// derivative 0 (as ceil): a parameter that only moves a value across cells (the injection shift) has no
// useful derivative, and the fit takes central differences for it (fit_problem.h).

#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace lpvlab {

// Dual and its functions live in a namespace of their own, found by argument-dependent lookup
// alone: code in lpvlab that calls exp or floor on a float must not find the Dual overloads
// (a float converts to a Dual implicitly).
namespace dual_number {

// Four parameters per pass: the fits ship with two to four; a fit of more differentiates four at a
// time, one pass each.
inline constexpr int kDualSlots = 4;

struct Dual {
  double a;               // the value
  double v[kDualSlots];   // d a / d parameter j

  // Trivial, as a double's (GLM's unions need it): `Dual x;` is uninitialised, `Dual x{}` and
  // std::vector<Dual>(n) are zero.
  Dual() = default;
  // Implicit, as GLSL converts a literal (a constant: no derivatives).
  constexpr Dual(double value) : a(value), v{} {}
  // The parameter in slot `slot` at `value`: derivative 1 there.
  static constexpr Dual parameter(double value, int slot) {
    Dual d(value);
    d.v[slot] = 1.0;
    return d;
  }
  explicit constexpr operator double() const { return a; }
  explicit constexpr operator float() const { return float(a); }
  explicit constexpr operator int() const { return int(a); }

  // A value whose derivatives are those of this one times `scale`, with value `value`: the chain
  // rule of a scalar function f at a, with f(a) = value and f'(a) = scale.
  constexpr Dual chain(double value, double scale) const {
    Dual d(value);
    for (int j = 0; j < kDualSlots; ++j) d.v[j] = scale * v[j];
    return d;
  }
  constexpr bool hasDerivatives() const {
    for (double x : v)
      if (x != 0.0) return true;
    return false;
  }

  constexpr Dual& operator+=(const Dual& o) {
    a += o.a;
    for (int j = 0; j < kDualSlots; ++j) v[j] += o.v[j];
    return *this;
  }
  constexpr Dual& operator-=(const Dual& o) {
    a -= o.a;
    for (int j = 0; j < kDualSlots; ++j) v[j] -= o.v[j];
    return *this;
  }
  constexpr Dual& operator*=(const Dual& o) {
    for (int j = 0; j < kDualSlots; ++j) v[j] = v[j] * o.a + a * o.v[j];
    a *= o.a;
    return *this;
  }
  constexpr Dual& operator/=(const Dual& o) {
    const double inverse = 1.0 / o.a, q = a * inverse;
    for (int j = 0; j < kDualSlots; ++j) v[j] = (v[j] - q * o.v[j]) * inverse;
    a = q;
    return *this;
  }
};

constexpr Dual operator+(Dual x) { return x; }
constexpr Dual operator-(Dual x) {
  x.a = -x.a;
  for (double& d : x.v) d = -d;
  return x;
}
constexpr Dual operator+(Dual x, const Dual& y) { return x += y; }
constexpr Dual operator-(Dual x, const Dual& y) { return x -= y; }
constexpr Dual operator*(Dual x, const Dual& y) { return x *= y; }
constexpr Dual operator/(Dual x, const Dual& y) { return x /= y; }
// With a plain number: no derivative products to form.
constexpr Dual operator*(Dual x, double s) {
  x.a *= s;
  for (double& d : x.v) d *= s;
  return x;
}
constexpr Dual operator*(double s, const Dual& x) { return x * s; }
constexpr Dual operator/(const Dual& x, double s) { return x * (1.0 / s); }

constexpr bool operator==(const Dual& x, const Dual& y) { return x.a == y.a; }
constexpr bool operator!=(const Dual& x, const Dual& y) { return x.a != y.a; }
constexpr bool operator<(const Dual& x, const Dual& y) { return x.a < y.a; }
constexpr bool operator>(const Dual& x, const Dual& y) { return x.a > y.a; }
constexpr bool operator<=(const Dual& x, const Dual& y) { return x.a <= y.a; }
constexpr bool operator>=(const Dual& x, const Dual& y) { return x.a >= y.a; }

// The functions the shared GLSL and the kernels call (found by argument-dependent lookup).
inline Dual sqrt(const Dual& x) {
  const double s = std::sqrt(x.a);
  return x.chain(s, 0.5 / s);
}
inline Dual inversesqrt(const Dual& x) { return Dual(1.0) / sqrt(x); }
inline Dual exp(const Dual& x) {
  const double e = std::exp(x.a);
  return x.chain(e, e);
}
inline Dual log(const Dual& x) { return x.chain(std::log(x.a), 1.0 / x.a); }
// x^y for x > 0 (the shared GLSL's Phong lobes); as Ceres's pow, d/dy = log(x) x^y.
inline Dual pow(const Dual& x, const Dual& y) {
  const double p = std::pow(x.a, y.a);
  Dual d(p);
  const double dx = y.a * std::pow(x.a, y.a - 1.0), dy = x.a > 0.0 ? std::log(x.a) * p : 0.0;
  for (int j = 0; j < kDualSlots; ++j) d.v[j] = dx * x.v[j] + dy * y.v[j];
  return d;
}
inline Dual abs(const Dual& x) { return x.a < 0.0 ? -x : x; }
inline Dual floor(const Dual& x) { return Dual(std::floor(x.a)); }
inline Dual ceil(const Dual& x) { return Dual(std::ceil(x.a)); }
inline Dual max(const Dual& x, const Dual& y) { return x < y ? y : x; }
inline Dual min(const Dual& x, const Dual& y) { return y < x ? y : x; }
inline Dual clamp(const Dual& x, const Dual& lo, const Dual& hi) { return min(max(x, lo), hi); }
// Exactly zero with no derivatives (a float: exactly zero), e.g. a GV value that blocks nothing.
inline bool isExactlyZero(const Dual& x) { return x.a == 0.0 && !x.hasDerivatives(); }
inline bool isExactlyZero(float x) { return x == 0.0f; }
inline bool isfinite(const Dual& x) {
  if (!std::isfinite(x.a)) return false;
  for (double d : x.v)
    if (!std::isfinite(d)) return false;
  return true;
}

// GLM's vectors of Dual with a plain number on one side (`p - 0.5`): GLM's own operators deduce
// one type for both and find none.
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> operator+(glm::vec<L, Dual, Q> v, double s) { return v + glm::vec<L, Dual, Q>(Dual(s)); }
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> operator-(glm::vec<L, Dual, Q> v, double s) { return v - glm::vec<L, Dual, Q>(Dual(s)); }
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> operator*(glm::vec<L, Dual, Q> v, double s) { return v * Dual(s); }
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> operator/(glm::vec<L, Dual, Q> v, double s) { return v / Dual(s); }
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> operator+(double s, glm::vec<L, Dual, Q> v) { return glm::vec<L, Dual, Q>(Dual(s)) + v; }
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> operator-(double s, glm::vec<L, Dual, Q> v) { return glm::vec<L, Dual, Q>(Dual(s)) - v; }
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> operator*(double s, glm::vec<L, Dual, Q> v) { return Dual(s) * v; }
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> clamp(glm::vec<L, Dual, Q> x, const Dual& lo, const Dual& hi) {
  for (glm::length_t i = 0; i < L; ++i) x[i] = clamp(x[i], lo, hi);
  return x;
}
// Per component, where GLM passes std::floor as a function pointer (no overload for Dual).
template <glm::length_t L, glm::qualifier Q>
glm::vec<L, Dual, Q> floor(glm::vec<L, Dual, Q> v) {
  for (glm::length_t i = 0; i < L; ++i) v[i] = floor(v[i]);
  return v;
}

}  // namespace dual_number

using dual_number::Dual;
using dual_number::kDualSlots;

}  // namespace lpvlab

// GLM's common functions accept floating-point types only (they ask numeric_limits), as Ceres
// declares its Jet one.
template <>
struct std::numeric_limits<lpvlab::Dual> : std::numeric_limits<double> {};
