#pragma once
// Lighting every pixel of the G-buffer by a set of VPLs (seed 001, 2.3, equation 11), with the
// clamp of 2.6 (equation 12): each VPL adds flux / pi * min(c, G f_r) to a pixel (vpl.h), G =
// cos(theta_vpl) cos(theta_x) / d^2 * V and f_r = albedo / pi per channel. What the clamp takes
// away is counted as it is taken, pixel by pixel (the radiance the image lacks), so a run
// reports the energy its clamp removed.
//
// Visibility V: exact, by an Embree shadow ray per (pixel, VPL) pair that faces each other; by
// the VPLs' shadow maps (vpl_depth_maps.h: exact or imperfect); or none (V = 1, as
// reflective-shadow-map gathering assumes). Pairs closer than `minDistance` are
// left out: G is unbounded there and the pair's light is the singularity the clamp exists for
// (without a clamp, such a pair could only add an Inf).

#include <cstddef>
#include <span>

#include "framework/many_lights/vpl.h"
#include "framework/many_lights/vpl_transfer.h"
#include "framework/pipeline/host_readback.h"

namespace lpvlab {

class EmbreeScene;
struct VplDepthMaps;

enum class GatherVisibility { None, Rays, DepthMaps };

struct GatherSettings {
  float clamp = 0.0f;  // c, 1/(m^2 sr); 0: no clamp (it bounds T of vpl_transfer.h alike)
  GatherVisibility visibility = GatherVisibility::Rays;
  float minDistance = 1e-4f;  // m; at least 4 ray epsilons when tracing shadow rays
  // Glossy receivers and spherical lights (vpl_transfer.h); the default: Lambertian points.
  ReceiverLobe lobe;
};

// Sums over the gathered pixels (their RGB channels summed), for the run's statistics.
struct GatherCounts {
  double pairs = 0.0;        // (pixel, VPL) pairs that face each other
  double shadowRays = 0.0;
  double radiance = 0.0;     // W/(m^2 sr): what the gather wrote
  double clampedAway = 0.0;  // W/(m^2 sr): what the clamp removed
  double largestGfr = 0.0;   // the largest G f_r of a visible pair, before the clamp, 1/(m^2 sr)
};

// G f_r of one VPL at a receiver (x, unit n_x, albedo), without visibility: zero when they face
// away from each other or are closer than minDistance; `toVpl` and `distance` are set when not.
inline glm::vec3 vplGeometryTerm(const glm::vec3& x, const glm::vec3& nx, const glm::vec3& albedo,
                                 const Vpl& vpl, float minDistance, glm::vec3& toVpl,
                                 float& distance) {
  const glm::vec3 d = vpl.position - x;
  const float d2 = glm::dot(d, d);
  if (!(d2 > minDistance * minDistance)) return glm::vec3(0.0f);
  distance = std::sqrt(d2);
  toVpl = d / distance;
  const float cosX = glm::dot(nx, toVpl), cosVpl = -glm::dot(vpl.normal, toVpl);
  if (cosX <= 0.0f || cosVpl <= 0.0f) return glm::vec3(0.0f);
  return albedo * (cosX * cosVpl / (d2 * float(M_PI)));
}

// The clamp of one pair: adds flux / pi * min(c, gfr) to `sum` and what the clamp removed to
// `removed` (per channel).
inline void addClamped(const glm::vec3& flux, const glm::vec3& gfr, float clamp, glm::dvec3& sum,
                       glm::dvec3& removed) {
  const glm::vec3 kept = clamp > 0.0f ? glm::min(gfr, glm::vec3(clamp)) : gfr;
  const glm::vec3 scale = flux * float(1.0 / M_PI);
  sum += glm::dvec3(scale * kept);
  removed += glm::dvec3(scale * (gfr - kept));
}

// What the visibility reads: the scene for rays, the VPLs' maps (in `vpls`' order) for DepthMaps.
struct GatherVisibilitySource {
  const EmbreeScene* scene = nullptr;
  const VplDepthMaps* maps = nullptr;
};

// Adds every VPL's light to `indirect` (RGBA, bottom row first, the G-buffer's size) at each
// covered G-buffer pixel (position.w > 0). Throws an Error when the visibility's source is missing.
void gatherVpls(const HostImage& position, const HostImage& normal, const HostImage& albedo,
                std::span<const Vpl> vpls, const GatherSettings& settings,
                const GatherVisibilitySource& source, HostImage& indirect,
                GatherCounts* counts = nullptr);

}  // namespace lpvlab
