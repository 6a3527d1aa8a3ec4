#include "framework/particles/particle_system.h"

#include <cmath>

#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/reference/random.h"

namespace lpvlab {

namespace {

// The random stream of one birth: SplitMix64 keyed by (seed, emitter, k), so a particle's values
// depend on nothing else (framework/reference/random.h keys the path tracer's samples alike).
class BirthRandom {
public:
  BirthRandom(std::uint64_t seed, int emitter, std::int64_t k)
      : state_(mix64(mix64(mix64(seed) + std::uint64_t(emitter)) + std::uint64_t(k))) {}
  // Uniform in [0, 1), 53 bits.
  double uniform() {
    state_ += 0x9e3779b97f4a7c15ull;
    return double(mix64(state_) >> 11) * 0x1p-53;
  }
  double symmetric() { return 2.0 * uniform() - 1.0; }  // seed's Rand(): uniform in [-1, 1)

private:
  std::uint64_t state_;
};

// A unit vector uniform in solid angle within `halfAngle` of the unit `axis`.
glm::dvec3 inCone(const glm::dvec3& axis, double halfAngle, double u, double v) {
  const double cosTheta = 1.0 - u * (1.0 - std::cos(halfAngle));
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const double phi = 2.0 * M_PI * v;
  // Duff et al. 2017: an orthonormal basis around `axis` without a branch on a chosen axis.
  const double sign = std::copysign(1.0, axis.z);
  const double a = -1.0 / (sign + axis.z), b = axis.x * axis.y * a;
  const glm::dvec3 t(1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
  const glm::dvec3 s(b, sign + axis.y * axis.y * a, -axis.y);
  return sinTheta * (std::cos(phi) * t + std::sin(phi) * s) + cosTheta * axis;
}

// Shoemake's uniformly random rotation from three uniforms.
glm::dquat randomRotation(double u1, double u2, double u3) {
  const double r1 = std::sqrt(1.0 - u1), r2 = std::sqrt(u1);
  return glm::normalize(glm::dquat(r2 * std::cos(2 * M_PI * u3), r1 * std::sin(2 * M_PI * u2),
                                   r1 * std::cos(2 * M_PI * u2), r2 * std::sin(2 * M_PI * u3)));
}

glm::dvec3 birthOffset(const Emitter& e, BirthRandom& random) {
  const double u = random.uniform(), v = random.uniform(), w = random.uniform();
  switch (e.shape) {
    case EmitterShape::Point:
      return glm::dvec3(0.0);
    case EmitterShape::Sphere:  // uniform in the ball: radius by the cube root
      return e.radius * std::cbrt(u) * inCone(glm::dvec3(0, 0, 1), M_PI, v, w);
    case EmitterShape::Box:
      return e.halfExtent * glm::dvec3(2 * u - 1, 2 * v - 1, 2 * w - 1);
    case EmitterShape::Disk: {  // uniform on the disk orthogonal to the direction
      const glm::dvec3 inPlane = inCone(e.direction, 0.5 * M_PI, 1.0, v);
      return e.radius * std::sqrt(u) * inPlane;
    }
  }
  return glm::dvec3(0.0);
}

bool finite(const Particle& p) {
  const auto ok = [](const glm::dvec3& v) { return std::isfinite(v.x + v.y + v.z); };
  return ok(p.position) && ok(p.velocity) && std::isfinite(p.size) && ok(p.color);
}

}  // namespace

double ParticleSystem::longestLife(int emitter) const {
  const Emitter& e = emitters.at(std::size_t(emitter));
  return e.lifetime + e.lifetimeVariation;
}

std::size_t ParticleSystem::capacity(int emitter) const {
  // Births alive at t have t - L_max < t_k <= t: at most floor(rate L_max) + 1 of them.
  return std::size_t(std::floor(emitters.at(std::size_t(emitter)).rate * longestLife(emitter))) + 1;
}

std::size_t ParticleSystem::capacity() const {
  std::size_t total = 0;
  for (std::size_t e = 0; e < emitters.size(); ++e) total += capacity(int(e));
  return total;
}

Particle particleAt(const ParticleSystem& system, int emitter, std::int64_t k, double seconds) {
  const Emitter& e = system.emitters.at(std::size_t(emitter));
  BirthRandom random(system.seed, emitter, k);
  Particle p;
  p.emitter = emitter;
  p.index = k;
  // The draws come in a fixed order, each from the birth's own stream.
  p.lifetime = e.lifetime + random.symmetric() * e.lifetimeVariation;
  const double speed = e.speed + random.symmetric() * e.speedVariation;
  const glm::dvec3 offset = birthOffset(e, random);
  glm::dvec3 axis = e.direction;
  if (e.radial && e.shape == EmitterShape::Sphere && glm::length(offset) > 0.0)
    axis = glm::normalize(offset);
  const double du = random.uniform(), dv = random.uniform();
  const glm::dvec3 direction = inCone(axis, e.spread, du, dv);
  const double r1 = random.uniform(), r2 = random.uniform(), r3 = random.uniform();
  const double s1 = random.uniform(), s2 = random.uniform();
  const glm::dquat initial = system.randomRotation ? randomRotation(r1, r2, r3) : glm::dquat(1, 0, 0, 0);
  const glm::dvec3 spinAxis = inCone(glm::dvec3(0, 0, 1), M_PI, s1, s2);

  const double born = double(k) / e.rate;
  p.age = seconds - born;
  const glm::dvec3 v0 = speed * direction;
  p.position = e.position + offset + v0 * p.age + 0.5 * system.gravity * p.age * p.age;
  p.velocity = v0 + system.gravity * p.age;
  p.orientation = glm::normalize(glm::angleAxis(system.spin * p.age, spinAxis) * initial);
  const double lived = p.lifetime > 0.0 ? std::clamp(p.age / p.lifetime, 0.0, 1.0) : 0.0;
  p.size = system.sizeOverLife.empty() ? system.size : system.sizeOverLife.sample(lived);
  p.color = system.colorOverLife.empty() ? system.color : system.colorOverLife.sample(lived);
  return p;
}

std::vector<Particle> particlesAt(const ParticleSystem& system, double seconds) {
  std::vector<Particle> alive;
  for (std::size_t ei = 0; ei < system.emitters.size(); ++ei) {
    const int emitter = int(ei);
    const Emitter& e = system.emitters[ei];
    // Candidates: births in (t - L_max, t], and none before the system started (-prewarm).
    const std::int64_t first = std::int64_t(std::ceil(-system.prewarm * e.rate));
    const std::int64_t lo =
        std::max(first, std::int64_t(std::floor(e.rate * (seconds - system.longestLife(emitter)))) - 1);
    const std::int64_t hi = std::int64_t(std::floor(e.rate * seconds)) + 1;
    if (hi < lo) continue;
    std::vector<Particle> candidates(std::size_t(hi - lo + 1));
    std::vector<char> isAlive(candidates.size(), 0);
    tbb::parallel_for(std::size_t(0), candidates.size(), [&](std::size_t i) {
      Particle p = particleAt(system, emitter, lo + std::int64_t(i), seconds);
      isAlive[i] = p.age >= 0.0 && p.age < p.lifetime;
      candidates[i] = p;
    });
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (!isAlive[i]) continue;
      if (!finite(candidates[i]))
        throw Error("particle system '" + system.name + "', emitter '" + e.name + "' at " +
                    std::to_string(seconds) + " s: particle " + std::to_string(candidates[i].index) +
                    " is not finite (a time or speed too large)");
      alive.push_back(candidates[i]);
    }
  }
  return alive;
}

}  // namespace lpvlab
