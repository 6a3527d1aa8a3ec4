#pragma once
// What one VPL sends to one receiver, beyond the Lambertian point of vpl_gather.h: glossy receivers
// and virtual spherical lights (VSLs; Hasan, Krivanek, Walter and Bala 2009, cited by seed 001).
// A pair adds flux / pi * T to the receiver's radiance towards the eye (the clamp bounds T), with
//
//   point VPL:   T = cos(theta_vpl) cos(theta_x) / d^2 * f(w, wo)
//   VSL, radius r: T = cos(theta_vpl) / (pi r^2) * integral over the cone the sphere subtends of
//                      f(w, wo) max(0, cos(theta_w)) dw
//
// with w the direction to the VPL, wo the direction to the eye and f the receiver's BRDF: its
// albedo / pi, plus with a glossy receiver the modified Phong lobe of the reference
// (framework/reference/phong_brdf.h: rho_s (m + 2) / (2 pi) (w . r)^m; one lobe for every pixel,
// as LPV's "glossy" rendering has). The VSL spreads the VPL's light over a sphere seen as a disk
// of area pi r^2 (its radiance flux cos(theta_vpl) / (pi pi r^2)); far from it (d >> r) the cone's
// solid angle is pi r^2 / d^2 and T is the point's. Near it T stays bounded, by cos(theta_vpl) /
// (pi r^2) times the receiver's albedo: what a glossy receiver's spike and a corner's 1 / d^2 need.
// The cone's integral takes kConeSamples fixed, stratified directions (the same for every pair:
// no noise, and a VSL of radius near 0 is its point exactly), except for a Lambertian receiver
// that sees the whole cone, where it has a closed form. cos(theta_vpl) is taken at the sphere's
// centre, the VPL's visibility by one ray to it.

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "framework/many_lights/vpl.h"
#include "framework/reference/phong_brdf.h"

namespace lpvlab {

struct ReceiverLobe {
  float specularAlbedo = 0.0f;  // rho_s of every receiver; 0: Lambertian receivers
  float exponent = 32.0f;       // m
  float sphereRadius = 0.0f;    // VSL radius, m; 0: point VPLs
  glm::vec3 eye{0.0f};          // the camera's position: the receivers' view directions

  bool lambertianPoints() const { return specularAlbedo == 0.0f && sphereRadius == 0.0f; }
};

inline constexpr int kConeSide = 4, kConeSamples = kConeSide * kConeSide;

// T of one pair (per channel), without visibility, for receiver x (unit normal nx, albedo), as
// above; zero when they face away from each other or are closer than minDistance (points only:
// a VSL's T stays finite). `toVpl` and `distance` are set when not zero.
inline glm::vec3 vplTransfer(const glm::vec3& x, const glm::vec3& nx, const glm::vec3& albedo,
                             const Vpl& vpl, const ReceiverLobe& lobe, float minDistance,
                             glm::vec3& toVpl, float& distance) {
  const glm::vec3 d = vpl.position - x;
  const float d2 = glm::dot(d, d);
  const bool sphere = lobe.sphereRadius > 0.0f;
  if (!(d2 > (sphere ? 0.0f : minDistance * minDistance))) return glm::vec3(0.0f);
  distance = std::sqrt(d2);
  toVpl = d / distance;
  const float cosVpl = -glm::dot(vpl.normal, toVpl);
  if (cosVpl <= 0.0f) return glm::vec3(0.0f);
  const PhongBrdf phong{.diffuse = albedo, .specular = glm::vec3(lobe.specularAlbedo), .exponent = lobe.exponent};
  const glm::vec3 wo = glm::normalize(lobe.eye - x);
  // The BRDF for a direction above the receiver: its lobe only where the eye is above it too (the
  // diffuse part whatever the G-buffer normal's side, as the Lambertian gather has it).
  const bool lobeSeen = lobe.specularAlbedo > 0.0f && glm::dot(nx, wo) > 0.0f;
  const auto f = [&](const glm::vec3& w) {
    return lobeSeen ? phong.evaluate(nx, wo, w) : albedo * float(1.0 / M_PI);
  };
  if (!sphere) {
    const float cosX = glm::dot(nx, toVpl);
    if (cosX <= 0.0f) return glm::vec3(0.0f);
    return f(toVpl) * (cosX * cosVpl / d2);
  }
  // The cone of half-angle alpha = asin(min(1, r / d)) about toVpl, sampled on a stratified grid
  // of (cos theta, phi) cells: equal solid angles.
  const float sinAlpha = std::min(1.0f, lobe.sphereRadius / distance);
  const float cosAlpha = std::sqrt(std::max(0.0f, 1.0f - sinAlpha * sinAlpha));
  const float capHeight = sinAlpha * sinAlpha / (1.0f + cosAlpha);  // 1 - cos(alpha), no cancellation
  const float area = float(M_PI) * lobe.sphereRadius * lobe.sphereRadius;
  // A Lambertian receiver that sees the whole cone: integral of cos over it is (n . axis) pi
  // sin^2(alpha), in closed form (which makes the sphere its point beyond r).
  const float cosAxis = glm::dot(nx, toVpl);
  if (!lobeSeen && cosAxis >= sinAlpha)
    return albedo * (cosAxis * sinAlpha * sinAlpha * cosVpl / area);
  glm::vec3 tangent, bitangent;
  orthonormalBasis(toVpl, tangent, bitangent);
  glm::vec3 sum(0.0f);
  for (int i = 0; i < kConeSide; ++i)
    for (int j = 0; j < kConeSide; ++j) {
      const float cosTheta = 1.0f - (i + 0.5f) / kConeSide * capHeight;
      const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
      const float phi = float(2.0 * M_PI) * (j + 0.5f) / kConeSide;
      const glm::vec3 w = sinTheta * (std::cos(phi) * tangent + std::sin(phi) * bitangent) + cosTheta * toVpl;
      const float cosW = glm::dot(nx, w);
      if (cosW > 0.0f) sum += f(w) * cosW;
    }
  const float solidAngle = float(2.0 * M_PI) * capHeight;
  return sum * (solidAngle / kConeSamples * cosVpl / area);
}

}  // namespace lpvlab
