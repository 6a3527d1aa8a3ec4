#pragma once
// A particle system (seed 002, 2.2): emitters that give birth to particles, each a copy of one
// model, which fly along a ballistic path, change colour and size over their life and die.
//
// The simulation is a closed form, not a stepped integration: particle k of an emitter is born
// at t_k = k / rate (k = 0, 1, ...; negative k for a system that is already running at 0 s,
// `prewarm`), draws every random property from a stream keyed by (seed, emitter, k), and at time
// t, of age a = t - t_k < its lifetime L_k, is at
//     p(t) = p_k + v_k a + g a^2 / 2
// (constant velocity plus gravity, exactly). So a frame is a pure function of its time: the same
// for any thread count, any order of evaluation and any frame a sequence resumes at, and nothing
// accumulates rounding over a long sequence. Seed 2.2.2's two ways of keeping the count up
// (resetting dead particles; P_n = P_m + Rand() P_v) both give a steady state of rate x mean
// lifetime particles; a constant birth rate is what lets the closed form exist.
//
// Units: metres, seconds, radians inside (degrees in files), linear RGB.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "framework/animation/keyframe_track.h"

namespace lpvlab {

// Where an emitter gives birth (seed 2.2.1, "Pozice", fig. 2.7): uniformly in its volume or on
// its disk.
enum class EmitterShape { Point, Sphere, Box, Disk };

struct Emitter {
  std::string name;
  EmitterShape shape = EmitterShape::Point;
  glm::dvec3 position{0.0};   // the shape's centre, world space
  double radius = 0.0;        // Sphere, Disk
  glm::dvec3 halfExtent{0.0}; // Box
  double rate = 10.0;         // births per second, evenly spaced (> 0)
  // Initial direction: the unit `direction` turned by an angle uniform in solid angle within the
  // cone of half-angle `spread` (0: all along `direction`; pi: any direction). A Disk lies in the
  // plane orthogonal to `direction`. With `radial`, a Sphere's particles leave along the line from
  // its centre instead (seed: "from the centre of the sphere"), before the spread.
  glm::dvec3 direction{0, 1, 0};
  double spread = 0.0;        // radians, [0, pi]
  bool radial = false;
  // Seed eq. 2.4, S_i = S_m + Rand() S_v with Rand() uniform in [-1, 1]; the same for lifetime.
  double speed = 1.0, speedVariation = 0.0;        // m/s; speed - variation >= 0
  double lifetime = 1.0, lifetimeVariation = 0.0;  // s; lifetime - variation > 0
};

// One live particle at a moment.
struct Particle {
  int emitter = 0;
  std::int64_t index = 0;   // k: its birth number within the emitter (keys its random stream)
  double age = 0.0;         // seconds since birth, [0, lifetime)
  double lifetime = 0.0;
  glm::dvec3 position{0.0};
  glm::dvec3 velocity{0.0};
  glm::dquat orientation{1, 0, 0, 0};
  double size = 1.0;        // metres: the model's largest extent is scaled to this
  glm::dvec3 color{1.0};    // multiplies the model's albedo, each channel in [0, 1]
};

struct ParticleSystem {
  std::string name;
  std::vector<Emitter> emitters;
  glm::dvec3 gravity{0, -9.81, 0};  // m/s^2
  std::uint64_t seed = 1;
  double prewarm = 0.0;             // seconds the system has been running at time 0
  // Orientation: uniformly random at birth with `randomRotation` (else the model as loaded), then
  // turning at `spin` rad/s about an axis uniformly random per particle.
  bool randomRotation = true;
  double spin = 0.0;
  // Over the life, keyed at the fraction of it lived (0 at birth, 1 at death): colour (linear
  // RGB multiplying the model's albedo) and size (metres). Linear between keys; an empty track
  // holds `color` or `size`.
  KeyframeTrack<glm::dvec3> colorOverLife;
  KeyframeTrack<double> sizeOverLife;
  glm::dvec3 color{1.0};
  double size = 0.1;

  // The most particles alive at once, at any time: per emitter floor(rate * longest life) + 1.
  std::size_t capacity() const;
  std::size_t capacity(int emitter) const;
  double longestLife(int emitter) const;
};

// The particles alive at `seconds`, emitter by emitter, each emitter's in birth order.
// Deterministic: a function of (system, seconds) alone. Throws an Error when a particle's values
// are not finite (a time so large that positions overflow).
std::vector<Particle> particlesAt(const ParticleSystem& system, double seconds);

// The particle that birth k of `emitter` is at `seconds`, alive or not (age may be negative or
// past its lifetime): the closed form above, for tests and for particlesAt.
Particle particleAt(const ParticleSystem& system, int emitter, std::int64_t k, double seconds);

}  // namespace lpvlab
