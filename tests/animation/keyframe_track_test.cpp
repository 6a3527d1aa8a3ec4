// KeyframeTrack against what its interpolations are defined to be: through every key, C1 in time
// (Catmull-Rom), the uniform spline of thesis eq. 6.4 where keys are evenly spaced, constant
// angular speed for slerp, and errors for keys out of order or not finite.
#include "framework/animation/keyframe_track.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtx/spline.hpp>
#include <limits>
#include <random>

#include "error_support.h"

namespace lpvlab {
namespace {

// Keys at uneven, increasing times with random values.
KeyframeTrack<glm::dvec3> randomTrack(std::mt19937& random, int count, Interpolation interpolation,
                                      std::vector<double>* timesOut = nullptr) {
  std::uniform_real_distribution<double> gap(0.05, 2.0), value(-10.0, 10.0);
  std::vector<double> times;
  std::vector<glm::dvec3> values;
  double t = gap(random) - 1.0;
  for (int i = 0; i < count; ++i) {
    times.push_back(t);
    values.emplace_back(value(random), value(random), value(random));
    t += gap(random);
  }
  if (timesOut) *timesOut = times;
  return KeyframeTrack<glm::dvec3>(times, values, interpolation);
}

TEST(KeyframeTrack, EveryInterpolationPassesThroughEveryKey) {
  std::mt19937 random(7);
  for (Interpolation interpolation :
       {Interpolation::Step, Interpolation::Linear, Interpolation::CatmullRom}) {
    std::vector<double> times;
    const KeyframeTrack<glm::dvec3> track = randomTrack(random, 9, interpolation, &times);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const glm::dvec3 v = track.sample(times[i]);
      EXPECT_NEAR(v.x, track.values()[i].x, 1e-12)
          << interpolationName(interpolation) << " key " << i;
      EXPECT_NEAR(v.z, track.values()[i].z, 1e-12)
          << interpolationName(interpolation) << " key " << i;
    }
  }
}

TEST(KeyframeTrack, CatmullRomIsContinuousWithAContinuousFirstDerivativeAtUnevenKeys) {
  std::mt19937 random(11);
  std::vector<double> times;
  const KeyframeTrack<glm::dvec3> track = randomTrack(random, 8, Interpolation::CatmullRom, &times);
  // One-sided differences on each side of every interior key: the cubic's error in them is
  // O(h), so with h = 1e-6 s the two sides agree to about 1e-5 of the values' scale.
  const double h = 1e-6;
  for (std::size_t i = 1; i + 1 < times.size(); ++i) {
    const double t = times[i];
    const glm::dvec3 left = (track.sample(t) - track.sample(t - h)) / h;
    const glm::dvec3 right = (track.sample(t + h) - track.sample(t)) / h;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(left[c], right[c], 1e-3 * (1.0 + std::abs(left[c]))) << "key " << i;
    // And the derivative is the finite difference of the neighbours (the definition).
    const glm::dvec3 expected =
        (track.values()[i + 1] - track.values()[i - 1]) / (times[i + 1] - times[i - 1]);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(right[c], expected[c], 1e-3 * (1.0 + std::abs(expected[c])));
  }
  // Linear is continuous but its derivative jumps at keys: the same check tells them apart.
  const KeyframeTrack<glm::dvec3> linear(track.times(), track.values(), Interpolation::Linear);
  int kinks = 0;
  for (std::size_t i = 1; i + 1 < times.size(); ++i) {
    const double t = times[i];
    const double left = ((linear.sample(t) - linear.sample(t - h)) / h).x;
    const double right = ((linear.sample(t + h) - linear.sample(t)) / h).x;
    kinks += std::abs(left - right) > 1e-3 * (1.0 + std::abs(left)) ? 1 : 0;
  }
  EXPECT_GT(kinks, 0);
}

TEST(KeyframeTrack, EvenlySpacedKeysGiveTheUniformCatmullRomSplineOfThesisEquation64) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> value(-5.0, 5.0);
  std::vector<double> times;
  std::vector<glm::dvec3> values;
  for (int i = 0; i < 6; ++i) {
    times.push_back(0.5 * i);
    values.emplace_back(value(random), value(random), value(random));
  }
  const KeyframeTrack<glm::dvec3> track(times, values, Interpolation::CatmullRom);
  // Eq. 6.4: x = 1/2 [1 n n^2 n^3] M [p0 p1 p2 p3]^T on the segment between p1 and p2.
  const double m[4][4] = {{0, 2, 0, 0}, {-1, 0, 1, 0}, {2, -5, 4, -1}, {-1, 3, -3, 1}};
  for (std::size_t i = 1; i + 2 < values.size(); ++i) {
    for (double n : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0}) {
      const double powers[4] = {1, n, n * n, n * n * n};
      glm::dvec3 thesis(0.0);
      for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
          thesis += 0.5 * powers[row] * m[row][col] * values[i - 1 + col];
      const glm::dvec3 ours = track.sample(times[i] + n * 0.5);
      const glm::dvec3 glms =
          glm::catmullRom(values[i - 1], values[i], values[i + 1], values[i + 2], n);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(ours[c], thesis[c], 1e-12) << "segment " << i << " n " << n;
        EXPECT_NEAR(glms[c], thesis[c], 1e-12);
      }
    }
  }
}

TEST(KeyframeTrack, LinearAndStepBetweenKeysAndHeldOutsideThem) {
  const KeyframeTrack<double> linear({1.0, 3.0}, {10.0, 20.0}, Interpolation::Linear);
  EXPECT_DOUBLE_EQ(linear.sample(2.0), 15.0);
  EXPECT_DOUBLE_EQ(linear.sample(2.5), 17.5);
  EXPECT_DOUBLE_EQ(linear.sample(-100.0), 10.0);
  EXPECT_DOUBLE_EQ(linear.sample(1e300), 20.0);
  const KeyframeTrack<double> step({1.0, 3.0}, {10.0, 20.0}, Interpolation::Step);
  EXPECT_DOUBLE_EQ(step.sample(2.999), 10.0);
  EXPECT_DOUBLE_EQ(step.sample(3.0), 20.0);
  // One key: a constant, whatever the interpolation.
  const KeyframeTrack<double> single({0.0}, {4.0}, Interpolation::CatmullRom);
  EXPECT_DOUBLE_EQ(single.sample(-1.0), 4.0);
  EXPECT_DOUBLE_EQ(single.sample(7.0), 4.0);
  // Two keys: the Catmull-Rom with one-sided end tangents is the straight line.
  const KeyframeTrack<double> two({0.0, 2.0}, {0.0, 8.0}, Interpolation::CatmullRom);
  EXPECT_NEAR(two.sample(0.5), 2.0, 1e-12);
  EXPECT_NEAR(two.sample(1.5), 6.0, 1e-12);
}

TEST(KeyframeTrack, SlerpTurnsAtConstantAngularSpeedAlongTheShorterArc) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 2, 3));
  const double total = glm::radians(150.0);
  // The second key given as -q: the same rotation, which must not send the slerp the long way.
  const KeyframeTrack<glm::dquat> track(
      {0.0, 1.0}, {glm::dquat(1, 0, 0, 0), -glm::angleAxis(total, axis)}, Interpolation::Linear);
  for (double s : {0.0, 0.2, 0.5, 0.9, 1.0}) {
    const glm::dquat q = track.sample(s);
    EXPECT_NEAR(glm::angle(q), s * total, 1e-9) << s;
    if (s > 0) {
      const glm::dvec3 a = glm::axis(q);
      EXPECT_NEAR(glm::dot(a, axis), 1.0, 1e-9);
    }
  }
}

TEST(KeyframeTrack, SquadPassesThroughEveryRotationKeyWithUnitQuaternions) {
  std::vector<double> times = {0.0, 1.0, 2.0, 3.0};
  std::vector<glm::dquat> keys = {glm::angleAxis(0.0, glm::dvec3(0, 1, 0)),
                                  glm::angleAxis(0.8, glm::dvec3(0, 1, 0)),
                                  glm::angleAxis(1.1, glm::normalize(glm::dvec3(1, 1, 0))),
                                  glm::angleAxis(2.0, glm::dvec3(0, 0, 1))};
  const KeyframeTrack<glm::dquat> track(times, keys, Interpolation::CatmullRom);
  for (std::size_t i = 0; i < keys.size(); ++i)
    EXPECT_NEAR(std::abs(glm::dot(track.sample(times[i]), keys[i])), 1.0, 1e-12) << i;
  for (double t = 0.0; t <= 3.0; t += 0.05) {
    const glm::dquat q = track.sample(t);
    EXPECT_NEAR(glm::length(q), 1.0, 1e-12);
    // Continuous: no jump between nearby times.
    EXPECT_GT(std::abs(glm::dot(q, track.sample(t + 1e-4))), 1.0 - 1e-6) << t;
  }
}

TEST(KeyframeTrack, KeysOutOfOrderOrNotFiniteAreErrors) {
  using test::contains;
  using test::errorOf;
  EXPECT_TRUE(contains(errorOf([] {
                         KeyframeTrack<double>({0.0, 1.0, 1.0}, {1, 2, 3}, Interpolation::Linear);
                       }),
                       "key 2: time 1.000000 s does not come after"));
  EXPECT_TRUE(contains(errorOf([] {
                         KeyframeTrack<double>({2.0, 1.0}, {1, 2}, Interpolation::Linear);
                       }),
                       "does not come after"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(errorOf([&] {
                         KeyframeTrack<double>({0.0, 1.0}, {1, nan}, Interpolation::Linear);
                       }),
                       "key 1: value is not finite"));
  EXPECT_TRUE(contains(errorOf([&] { KeyframeTrack<double>({nan}, {1}, Interpolation::Linear); }),
                       "time is not finite"));
  EXPECT_TRUE(contains(errorOf([] { KeyframeTrack<double>({}, {}, Interpolation::Linear); }),
                       "at least one key"));
  EXPECT_TRUE(contains(errorOf([] {
                         KeyframeTrack<glm::dquat>({0.0}, {glm::dquat(0, 0, 0, 0)},
                                                   Interpolation::Linear);
                       }),
                       "zero rotation"));
}

TEST(KeyframeTrack, ValuesStayFiniteAtExtremeTimesAndSpans) {
  // Keys a nanosecond apart and a year apart, sampled far outside and inside.
  const KeyframeTrack<glm::dvec3> tiny(
      {0.0, 1e-9, 2e-9}, {glm::dvec3(0), glm::dvec3(1), glm::dvec3(0)}, Interpolation::CatmullRom);
  const KeyframeTrack<glm::dvec3> huge({0.0, 3e7, 6e7},
                                       {glm::dvec3(1e30), glm::dvec3(-1e30), glm::dvec3(0)},
                                       Interpolation::CatmullRom);
  for (double t : {-1e300, 0.0, 5e-10, 1.5e-9, 1e7, 4.5e7, 1e300}) {
    EXPECT_TRUE(std::isfinite(tiny.sample(t).x)) << t;
    EXPECT_TRUE(std::isfinite(huge.sample(t).x)) << t;
  }
}

}  // namespace
}  // namespace lpvlab
