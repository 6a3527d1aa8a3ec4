// The clamp compensation (framework/many_lights/clamp_compensation.h) against numerical
// integration: in an open corner lit by a point light, the one-bounce light that a floor point
// receives from the wall has a closed-form integrand, so the compensation's expectation, the
// integral of L_r(y) max(0, f_r G - c) over the wall, is a 2D quadrature. The Monte Carlo estimate
// must agree with it within its own standard error, per channel; a clamp above every G f_r must
// add exactly nothing, and a clamp near zero must give back the whole one-bounce light.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "framework/core/error.h"
#include "framework/many_lights/clamp_compensation.h"
#include "framework/many_lights/ray_scene.h"
#include "reference/test_scenes.h"

namespace lpvlab {
namespace {

constexpr float kHalf = 2.0f;           // the floor and wall's half width, m
const glm::vec3 kFloorAlbedo(0.8f, 0.5f, 0.3f);
constexpr float kWallAlbedo = 0.7f;
const glm::vec3 kLight(0.3f, 1.0f, 0.8f);
constexpr float kIntensity = 3.0f;      // W/sr

// The floor y = 0 for z in [0, 2] and the wall z = 0 for y in [0, 2], both 4 m wide (facing +y
// and +z), lit by a point light in front of both: every wall point sees the light.
Scene openCorner() {
  Scene scene;
  scene.source = "test:open corner";
  for (const glm::vec3 colour : {kFloorAlbedo, glm::vec3(kWallAlbedo)}) {
    Material material;
    material.name = "m" + std::to_string(scene.materials.size());
    material.baseColor = colour;
    scene.materials.push_back(material);
  }
  scene.meshes.push_back(testing::quad("floor", 0,
                                       {glm::vec3(-kHalf, 0, 2 * kHalf), glm::vec3(kHalf, 0, 2 * kHalf),
                                        glm::vec3(kHalf, 0, 0), glm::vec3(-kHalf, 0, 0)}));
  scene.meshes.push_back(testing::quad("wall", 1,
                                       {glm::vec3(-kHalf, 0, 0), glm::vec3(kHalf, 0, 0),
                                        glm::vec3(kHalf, 2 * kHalf, 0), glm::vec3(-kHalf, 2 * kHalf, 0)}));
  Light light;
  light.name = "bulb";
  light.type = LightType::Point;
  light.position = kLight;
  light.intensity = kIntensity;
  scene.lights.push_back(light);
  return scene;
}

// The integral over the wall of L_r(y) max(0, f_r G - c) (c = 0: L_r(y) f_r G) at the floor point
// (px, 0, pz), by the midpoint rule on a fine grid over the part of the wall within r_c.
glm::dvec3 quadrature(double px, double pz, double clamp) {
  const double reach = clamp > 0.0 ? std::sqrt(double(kFloorAlbedo.r) / (M_PI * clamp)) : 1e9;
  const double x0 = std::max(-double(kHalf), px - reach), x1 = std::min(double(kHalf), px + reach);
  const double y1 = std::min(2.0 * kHalf, reach);
  constexpr int kCells = 1500;
  const double dx = (x1 - x0) / kCells, dy = y1 / kCells;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const glm::dvec3 y(x0 + (i + 0.5) * dx, (j + 0.5) * dy, 0.0);
      const glm::dvec3 toLight = glm::dvec3(kLight) - y;
      const double r2 = glm::dot(toLight, toLight);
      const double reflected = kWallAlbedo / M_PI * kIntensity * (toLight.z / std::sqrt(r2)) / r2;
      const glm::dvec3 d = glm::dvec3(px, 0.0, pz) - y;
      const double d2 = glm::dot(d, d), distance = std::sqrt(d2);
      const double g = (y.y / distance) * (pz / distance) / d2;  // cos at the floor, at the wall
      for (int c = 0; c < 3; ++c) {
        const double gfr = kFloorAlbedo[c] / M_PI * g;
        sum[c] += reflected * std::max(0.0, gfr - clamp) * dx * dy;
      }
    }
  return sum;
}

// `count` copies of the floor point (px, 0, pz) as a G-buffer row, each pixel its own samples.
struct Receivers {
  HostImage position, normal, albedo, out;
};

Receivers floorPoints(float px, float pz, int count) {
  Receivers r;
  for (HostImage* image : {&r.position, &r.normal, &r.albedo, &r.out}) {
    image->width = count;
    image->height = 1;
  }
  r.position.texels.assign(count, glm::vec4(px, 0.0f, pz, 1.0f));
  r.normal.texels.assign(count, glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
  r.albedo.texels.assign(count, glm::vec4(kFloorAlbedo, 1.0f));
  r.out.texels.assign(count, glm::vec4(0.0f));
  return r;
}

struct Estimate {
  glm::dvec3 mean{0.0}, standardError{0.0};
  ClampCompensationCounts counts;
};

Estimate compensate(const RayScene& scene, float px, float pz, float clamp, int pixels, int samples) {
  Receivers r = floorPoints(px, pz, pixels);
  ClampCompensationSettings settings;
  settings.clamp = clamp;
  settings.samples = samples;
  settings.maxScatterings = 2;  // one bounce: the wall's direct light, reflected at the floor
  Estimate e;
  compensateClamp(r.position, r.normal, r.albedo, scene, settings, r.out, &e.counts);
  glm::dvec3 sum(0.0), squares(0.0);
  for (const glm::vec4& v : r.out.texels) {
    sum += glm::dvec3(v);
    squares += glm::dvec3(v) * glm::dvec3(v);
  }
  e.mean = sum / double(pixels);
  const glm::dvec3 variance = (squares / double(pixels) - e.mean * e.mean) * (pixels / (pixels - 1.0));
  e.standardError = glm::sqrt(glm::max(variance, glm::dvec3(0.0)) / double(pixels));
  return e;
}

TEST(ClampCompensation, WeightIsTheClampedAwayShareOfEachChannel) {
  const glm::vec3 rho(0.8f, 0.4f, 0.0f);
  // f_r G = rho / pi * 0.5 * 1 / 0.25 = rho * 2 / pi: 0.509 and 0.255 and 0.
  const glm::vec3 w = clampCompensationWeight(rho, 0.5f, 1.0f, 0.5f, 0.3f, 1e-4f);
  EXPECT_NEAR(w.r, 1.0 - 0.3 / (0.8 * 2 / M_PI), 1e-6);
  EXPECT_EQ(w.g, 0.0f);  // 0.255 < c: nothing clamped
  EXPECT_EQ(w.b, 0.0f);
  EXPECT_EQ(clampCompensationWeight(rho, -0.1f, 1.0f, 0.5f, 0.3f, 1e-4f), glm::vec3(0.0f));
  EXPECT_EQ(clampCompensationWeight(rho, 0.5f, 0.0f, 0.5f, 0.3f, 1e-4f), glm::vec3(0.0f));
  // Closer than the gather's minimum distance the gather kept nothing: all comes back.
  EXPECT_EQ(clampCompensationWeight(rho, 0.5f, 1.0f, 5e-5f, 0.3f, 1e-4f), glm::vec3(1.0f));
}

TEST(ClampCompensation, MatchesTheIntegralOfTheClampedAwayLight) {
  const RayScene scene(openCorner());
  for (const float pz : {0.05f, 0.2f})
    for (const float clamp : {0.5f, 2.0f}) {
      const glm::dvec3 expected = quadrature(0.1, pz, clamp);
      const Estimate e = compensate(scene, 0.1f, pz, clamp, 4096, 16);
      std::cout << "z " << pz << ", c " << clamp << ": estimate (" << e.mean.r << ", " << e.mean.g
                << ", " << e.mean.b << ") +- (" << e.standardError.r << ", " << e.standardError.g
                << ", " << e.standardError.b << "), integral (" << expected.r << ", " << expected.g
                << ", " << expected.b << "); weighted paths "
                << e.counts.weightedPaths / e.counts.paths << "\n";
      ASSERT_GT(expected.r, 0.0);
      for (int c = 0; c < 3; ++c) {
        if (expected[c] == 0.0) {
          EXPECT_EQ(e.mean[c], 0.0);
          continue;
        }
        EXPECT_LT(std::abs(e.mean[c] - expected[c]), 4.0 * e.standardError[c] + 1e-4 * expected[c])
            << "channel " << c;
      }
    }
}

TEST(ClampCompensation, AClampAboveEveryGfrAddsNothing) {
  const RayScene scene(openCorner());
  // At z = 0.3 every wall point is at least 0.3 m away: f_r G <= 0.8 / pi / 0.09 < 2.9.
  const Estimate e = compensate(scene, 0.1f, 0.3f, 3.0f, 64, 16);
  EXPECT_EQ(e.mean, glm::dvec3(0.0));
  EXPECT_EQ(e.counts.weightedPaths, 0.0);
  EXPECT_EQ(e.counts.compensatedPixels, 0.0);
  EXPECT_EQ(e.counts.paths, 64.0 * 16.0);
}

TEST(ClampCompensation, ANearZeroClampGivesBackTheWholeOneBounceLight) {
  const RayScene scene(openCorner());
  const glm::dvec3 expected = quadrature(0.1, 0.4, 0.0);
  const Estimate e = compensate(scene, 0.1f, 0.4f, 1e-7f, 2048, 16);
  for (int c = 0; c < 3; ++c)
    EXPECT_LT(std::abs(e.mean[c] - expected[c]), 4.0 * e.standardError[c] + 1e-3 * expected[c])
        << "channel " << c << ": " << e.mean[c] << " against " << expected[c];
}

TEST(ClampCompensation, RefusesWhatItCannotCompensate) {
  const RayScene scene(openCorner());
  Receivers r = floorPoints(0.0f, 0.1f, 2);
  ClampCompensationSettings settings;
  for (const float clamp : {0.0f, -1.0f, std::numeric_limits<float>::infinity()}) {
    settings.clamp = clamp;
    EXPECT_THROW(compensateClamp(r.position, r.normal, r.albedo, scene, settings, r.out), Error);
  }
  settings.clamp = 1.0f;
  settings.samples = 0;
  EXPECT_THROW(compensateClamp(r.position, r.normal, r.albedo, scene, settings, r.out), Error);
  settings.samples = 1;
  r.out.width = 3;
  EXPECT_THROW(compensateClamp(r.position, r.normal, r.albedo, scene, settings, r.out), Error);
}

}  // namespace
}  // namespace lpvlab
