#pragma once
// VPLs from light paths (seed 001, 2.1): random walks from the scene's punctual lights. A walk
// starts at a light chosen with probability proportional to its power (luminance), carrying that
// light's flux divided by the chance of its choice and by the number of walks; every surface it
// hits becomes a VPL reflecting the flux that arrived times the albedo there; it continues in a
// cosine-distributed direction, from the `rouletteAfter`-th VPL on only with probability
// min(0.95, largest albedo channel), its flux divided by that probability (Russian roulette:
// unbiased). With `firstHitsOnly` it stops at its first hit: the VPLs then carry the light that
// has been reflected once, what a pixel's one-bounce indirect light (the reference's `indirect1`)
// is made of.
//
// The emission a light's walks start with, for its power P (W per channel):
//   point        uniform directions over the sphere, P = 4 pi I
//   spot         uniform directions in the outer cone, each weighted by the cone's falloff;
//                P = 2 pi I * integral of the falloff over cos(theta) from cos(outer) to 1
//   directional  uniform points on a disk across the light that covers the scene's bounds,
//                P = E * disk area
// Walk i draws from its own stream (seed, i), so the VPLs do not depend on the thread count; with
// the Sobol sampler (random.h) walk i is point i of one Owen-scrambled Sobol sequence of `seed`,
// so the walks' first choices (the light, the emitted direction, the first bounce) are stratified
// over the walks.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "framework/many_lights/ray_scene.h"
#include "framework/many_lights/vpl.h"
#include "framework/reference/random.h"

namespace lpvlab {

struct LightPathSettings {
  int paths = 256;             // walks started per frame, over all lights
  bool firstHitsOnly = false;  // one-bounce VPLs only
  int rouletteAfter = 1;       // VPLs a walk makes before Russian roulette
  int maxBounces = 64;         // the most VPLs one walk makes
  std::uint64_t seed = 1;
  SampleSequence sampler = SampleSequence::Independent;  // [indirect] sampler
};

struct LightPathCounts {
  std::size_t vpls = 0;
  std::size_t rays = 0;        // traced (every bounce's ray, hit or not)
  glm::dvec3 emittedFlux{0.0}; // what the lights emit, W per channel (the walks' expectation)
};

// The emitted power of one light, W per channel (see above; `sceneRadius`: the directional
// light's disk radius).
glm::dvec3 lightPower(const PunctualLight& light, double sceneRadius);

// The walks' VPLs, in walk order; none when the lights emit nothing.
std::vector<Vpl> traceLightPaths(const RayScene& scene, const LightPathSettings& settings,
                                 LightPathCounts* counts = nullptr);

}  // namespace lpvlab
