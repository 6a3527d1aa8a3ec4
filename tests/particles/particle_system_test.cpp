// The particle simulation (framework/particles/particle_system.h) against what must hold
// whatever the implementation: a frame depends on its time and seed alone (not on the thread
// count or on the frames before), a particle flies the path a numerical integration of
// dv/dt = g gives and lands where the range formula of projectile motion says, births come at
// the rate, lives last as long as they should, and the random birth values follow the
// distributions the settings describe.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "framework/particles/particle_system.h"

namespace lpvlab {
namespace {

ParticleSystem fountain() {
  ParticleSystem system;
  system.name = "test";
  system.seed = 7;
  system.gravity = {0, -9.81, 0};
  system.spin = 2.0;
  Emitter e;
  e.name = "cone";
  e.shape = EmitterShape::Sphere;
  e.radius = 0.1;
  e.position = {1, 2, 3};
  e.direction = glm::normalize(glm::dvec3(0.2, 1, 0));
  e.spread = 0.4;
  e.rate = 500;
  e.speed = 2;
  e.speedVariation = 0.5;
  e.lifetime = 1.5;
  e.lifetimeVariation = 0.5;
  system.emitters.push_back(e);
  e.name = "box";
  e.shape = EmitterShape::Box;
  e.halfExtent = {0.5, 0.1, 0.2};
  e.rate = 120;
  system.emitters.push_back(e);
  return system;
}

void expectSame(const std::vector<Particle>& a, const std::vector<Particle>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].index, b[i].index);
    EXPECT_EQ(a[i].position, b[i].position) << i;  // bit for bit
    EXPECT_EQ(a[i].orientation, b[i].orientation) << i;
    EXPECT_EQ(a[i].size, b[i].size) << i;
  }
}

TEST(ParticleSimulation, AFrameIsTheSameForAnyThreadCountAndEvaluationOrder) {
  const ParticleSystem system = fountain();
  const std::vector<Particle> all = particlesAt(system, 3.21);
  ASSERT_GT(all.size(), 500u);
  std::vector<Particle> one;
  {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = particlesAt(system, 3.21);
  }
  expectSame(all, one);
  // Evaluating other frames first changes nothing (there is no state between frames).
  particlesAt(system, 0.5);
  particlesAt(system, 10.0);
  expectSame(all, particlesAt(system, 3.21));
}

TEST(ParticleSimulation, TheSeedDecidesTheRandomValues) {
  ParticleSystem a = fountain(), b = fountain();
  b.seed = 8;
  const std::vector<Particle> pa = particlesAt(a, 2.0), pb = particlesAt(b, 2.0);
  ASSERT_FALSE(pa.empty());
  ASSERT_FALSE(pb.empty());
  EXPECT_NE(pa.front().position, pb.front().position);
}

// Steps the particle from its birth state with velocity Verlet (exact for constant acceleration
// up to rounding, an independent computation of the same path) and compares with the closed form
// every 1000 steps.
TEST(ParticleSimulation, APathMatchesANumericalIntegrationOfGravity) {
  ParticleSystem system = fountain();
  system.gravity = {0.3, -9.81, -1.2};
  const Particle birth = particleAt(system, 0, 42, 42.0 / 500.0);  // age 0
  ASSERT_NEAR(birth.age, 0.0, 1e-12);
  glm::dvec3 x = birth.position, v = birth.velocity;
  const double dt = 1e-4;
  for (int step = 1; step <= 15000; ++step) {
    x += v * dt + 0.5 * system.gravity * dt * dt;
    v += system.gravity * dt;
    if (step % 1000) continue;
    const Particle p = particleAt(system, 0, 42, 42.0 / 500.0 + step * dt);
    EXPECT_NEAR(glm::length(p.position - x), 0.0, 1e-9) << step;
    EXPECT_NEAR(glm::length(p.velocity - v), 0.0, 1e-9) << step;
  }
}

TEST(ParticleSimulation, AProjectileLandsWhereTheRangeFormulaSays) {
  // Launched at 45 degrees with speed s from the ground, it lands after 2 s sin(45)/g at a range
  // of s^2 / g.
  ParticleSystem system;
  system.gravity = {0, -9.81, 0};
  Emitter e;
  e.position = {0, 0, 0};
  e.direction = glm::normalize(glm::dvec3(1, 1, 0));
  e.rate = 1;
  e.speed = 3;
  e.lifetime = 10;
  system.emitters.push_back(e);
  const double flight = 2.0 * 3.0 * std::sin(M_PI / 4) / 9.81;
  const Particle p = particleAt(system, 0, 0, flight);
  EXPECT_NEAR(p.position.x, 9.0 / 9.81, 1e-12);
  EXPECT_NEAR(p.position.y, 0.0, 1e-12);
  EXPECT_NEAR(p.position.z, 0.0, 1e-12);
}

TEST(ParticleSimulation, BirthsComeAtTheRateAndLiveTheirLifetime) {
  ParticleSystem system;
  Emitter e;
  e.rate = 40;
  e.lifetime = 0.5;  // rate x lifetime = 20 alive in the steady state
  system.emitters.push_back(e);
  EXPECT_EQ(system.capacity(), 21u);
  // Without prewarm the system starts empty at 0 s: births at 0, 1/40, ... up to t.
  EXPECT_EQ(particlesAt(system, 0.0).size(), 1u);
  EXPECT_EQ(particlesAt(system, 0.1 + 1e-9).size(), 5u);
  for (double t : {0.6, 1.0 + 1e-9, 7.3, 100.0}) {
    const std::vector<Particle> alive = particlesAt(system, t);
    EXPECT_GE(alive.size(), 20u) << t;
    EXPECT_LE(alive.size(), 21u) << t;
    for (const Particle& p : alive) {
      EXPECT_GE(p.age, 0.0);
      EXPECT_LT(p.age, 0.5);
    }
  }
  system.prewarm = 2.0;  // already running: the steady state from the start
  EXPECT_GE(particlesAt(system, 0.0).size(), 20u);
}

TEST(ParticleSimulation, VaryingLifetimesNeverExceedTheCapacity) {
  const ParticleSystem system = fountain();
  for (double t = 0.0; t < 6.0; t += 0.0137) {
    const std::vector<Particle> alive = particlesAt(system, t);
    EXPECT_LE(alive.size(), system.capacity()) << t;
    std::size_t perEmitter[2] = {0, 0};
    for (const Particle& p : alive) ++perEmitter[p.emitter];
    EXPECT_LE(perEmitter[0], system.capacity(0));
    EXPECT_LE(perEmitter[1], system.capacity(1));
  }
}

// The birth values of many particles against their distributions: every direction within the
// cone, cos(theta) uniform in [cos(spread), 1] (mean within 5 standard errors), positions in the
// ball with (r / R)^3 uniform, speeds and lifetimes in their ranges with the middle as mean.
TEST(ParticleSimulation, BirthValuesFollowTheirDistributions) {
  const ParticleSystem system = fountain();
  const Emitter& e = system.emitters[0];
  const int n = 20000;
  double sumCos = 0, sumR3 = 0, sumSpeed = 0, sumLife = 0;
  for (int k = 0; k < n; ++k) {
    const Particle p = particleAt(system, 0, k, double(k) / e.rate);  // at birth
    const double speed = glm::length(p.velocity);
    const double c = glm::dot(p.velocity / speed, e.direction);
    EXPECT_GE(c, std::cos(e.spread) - 1e-12);
    const double r = glm::length(p.position - e.position);
    EXPECT_LE(r, e.radius + 1e-12);
    EXPECT_GE(speed, e.speed - e.speedVariation - 1e-12);
    EXPECT_LE(speed, e.speed + e.speedVariation + 1e-12);
    EXPECT_GT(p.lifetime, 0.0);
    sumCos += c;
    sumR3 += std::pow(r / e.radius, 3.0);
    sumSpeed += speed;
    sumLife += p.lifetime;
  }
  const double lo = std::cos(e.spread);
  const auto uniformSe = [&](double width) { return width / std::sqrt(12.0 * n); };
  EXPECT_NEAR(sumCos / n, 0.5 * (1 + lo), 5 * uniformSe(1 - lo));
  EXPECT_NEAR(sumR3 / n, 0.5, 5 * uniformSe(1.0));
  EXPECT_NEAR(sumSpeed / n, e.speed, 5 * uniformSe(2 * e.speedVariation));
  EXPECT_NEAR(sumLife / n, e.lifetime, 5 * uniformSe(2 * e.lifetimeVariation));
}

TEST(ParticleSimulation, SizeAndColourFollowTheirKeysOverTheLife) {
  ParticleSystem system;
  Emitter e;
  e.rate = 1;
  e.lifetime = 2;
  system.emitters.push_back(e);
  system.sizeOverLife = KeyframeTrack<double>({0.0, 1.0}, {0.1, 0.5}, Interpolation::Linear);
  system.colorOverLife =
      KeyframeTrack<glm::dvec3>({0.0, 0.5}, {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)}, Interpolation::Linear);
  const Particle p = particleAt(system, 0, 0, 0.5);  // a quarter of its life
  EXPECT_NEAR(p.size, 0.2, 1e-12);
  EXPECT_NEAR(p.color.x, 0.5, 1e-12);
  EXPECT_NEAR(p.color.z, 0.5, 1e-12);
  const Particle late = particleAt(system, 0, 0, 1.5);
  EXPECT_NEAR(late.size, 0.4, 1e-12);
  EXPECT_NEAR(late.color.z, 1.0, 1e-12);
}

TEST(ParticleSimulation, SpinTurnsAtItsRateAboutAFixedAxis) {
  ParticleSystem system = fountain();
  system.spin = 1.5;
  const Particle a = particleAt(system, 1, 5, 0.1), b = particleAt(system, 1, 5, 0.9);
  // The rotation from a to b is by spin x 0.8 s.
  const glm::dquat between = b.orientation * glm::inverse(a.orientation);
  const double angle = 2.0 * std::acos(std::min(1.0, std::abs(between.w)));
  EXPECT_NEAR(angle, 1.5 * 0.8, 1e-9);
}

}  // namespace
}  // namespace lpvlab
