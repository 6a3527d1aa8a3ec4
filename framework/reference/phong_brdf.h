#pragma once
// The reference's glossy BRDF ([reference] brdf = "phong"): Lambertian diffuse plus the
// energy-conserving modified Phong lobe (Lafortune and Willems 1994), reciprocal by construction,
//
//   f(wi, wo) = rho_d / pi + rho_s (m + 2) / (2 pi) max(0, wi . r(wo))^m,   r(wo) = 2 (n . wo) n - wo,
//
// with rho_d the material's albedo (base colour x texture x vertex colour), rho_s its specular
// reflectance and m its exponent (Material::specular, Material::shininess). wi . r(wo) = wo . r(wi),
// so f(wi, wo) = f(wo, wi). The lobe's directional albedo, the integral over the hemisphere of
// (m + 2) / (2 pi) (wi . r)^m cos(theta_i), is 1 at normal incidence and less elsewhere (the lobe
// tilts away from the normal and dips below the horizon; Lafortune and Willems show it is largest
// at normal incidence, and tests/reference/phong_brdf_test.cpp checks it by quadrature). With
// rho_d + rho_s <= 1 per channel (the loaders and [[materials]] make sure) no direction reflects
// more than it receives (the white furnace test).
//
// It is the lobe LPV's "glossy" rendering integrates the grid against (docs/variants/glossy.md:
// (m + 1) / (2 pi) (w . r)^m, without the cosine of the incident direction), so a run's
// `exponent` and `specular_albedo` describe the same surface as the reference's m and rho_s; the
// two differ by that cosine, which is part of what the glossy ablation measures.
//
// Sampling: the diffuse lobe (cosine-distributed) with probability 1 - p_s, the Phong lobe about
// r ((m + 1) / (2 pi) (w . r)^m) with probability p_s = lum(rho_s) / (lum(rho_d) + lum(rho_s)); the
// density of a direction is the mixture's, so both are weighed together (one-sample MIS).

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "framework/reference/hemisphere_sampling.h"

namespace lpvlab {

struct PhongBrdf {
  glm::vec3 diffuse{0.0f};   // rho_d
  glm::vec3 specular{0.0f};  // rho_s
  float exponent = 0.0f;     // m >= 0

  bool glossy() const { return specular.r > 0.0f || specular.g > 0.0f || specular.b > 0.0f; }

  // The probability of sampling the Phong lobe.
  float specularProbability() const {
    const auto luminance = [](const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
    const float s = luminance(specular), d = luminance(diffuse);
    return s + d > 0.0f ? s / (s + d) : 0.0f;
  }

  // f(wi, wo) (1/sr per channel) about unit normal n (on wo's side); zero below the horizon.
  glm::vec3 evaluate(const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi) const {
    if (!(glm::dot(n, wi) > 0.0f && glm::dot(n, wo) > 0.0f)) return glm::vec3(0.0f);
    const float c = glm::dot(wi, reflect(n, wo));
    const float lobe = c > 0.0f ? (exponent + 2.0f) * float(0.5 / M_PI) * std::pow(c, exponent) : 0.0f;
    return diffuse * float(1.0 / M_PI) + specular * lobe;
  }

  // The sampling density of wi (1/sr).
  float pdf(const glm::vec3& n, const glm::vec3& wo, const glm::vec3& wi) const {
    const float cosine = glm::dot(n, wi);
    if (!(cosine > 0.0f)) return 0.0f;
    const float ps = specularProbability();
    const float c = glm::dot(wi, reflect(n, wo));
    const float lobe = c > 0.0f ? (exponent + 1.0f) * float(0.5 / M_PI) * std::pow(c, exponent) : 0.0f;
    return (1.0f - ps) * cosine * float(1.0 / M_PI) + ps * lobe;
  }

  // A direction from three uniform numbers (u0 picks the lobe); false when it falls below the
  // horizon (the path ends: that light is not reflected).
  bool sample(const glm::vec3& n, const glm::vec3& wo, float u0, float u1, float u2, glm::vec3& wi) const {
    if (u0 < specularProbability()) {
      // (w . r) = t with density (m + 1) t^m on [0, 1]: t = u^(1 / (m + 1)).
      const float t = std::pow(std::max(u1, 1e-30f), 1.0f / (exponent + 1.0f));
      const float s = std::sqrt(std::max(0.0f, 1.0f - t * t));
      const float phi = float(2.0 * M_PI) * u2;
      const glm::vec3 r = reflect(n, wo);
      glm::vec3 tangent, bitangent;
      orthonormalBasis(r, tangent, bitangent);
      wi = glm::normalize(s * std::cos(phi) * tangent + s * std::sin(phi) * bitangent + t * r);
    } else {
      wi = cosineHemisphere(n, u1, u2);
    }
    return glm::dot(n, wi) > 0.0f;
  }

  static glm::vec3 reflect(const glm::vec3& n, const glm::vec3& wo) {
    return 2.0f * glm::dot(n, wo) * n - wo;
  }
};

}  // namespace lpvlab
