// Pull-push (framework/many_lights/pull_push.h) exactly as seed 001, 3.3.1 states it, and
// imperfect shadow maps against exact ones (framework/many_lights/vpl_depth_maps.h).

#include <cmath>
#include <iostream>
#include <limits>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/many_lights/light_paths.h"
#include "framework/many_lights/paraboloid.h"
#include "framework/many_lights/pull_push.h"
#include "framework/many_lights/ray_scene.h"
#include "framework/many_lights/vpl_depth_maps.h"
#include "many_lights/plates_scene.h"

namespace lpvlab {
namespace {

constexpr float H = -1.0f;  // a hole

TEST(PullPush, AFullyDefinedMapIsUnchanged) {
  std::vector<float> map(64), scratch;
  for (std::size_t i = 0; i < map.size(); ++i) map[i] = float(i * 7 % 13) + 0.5f;
  const std::vector<float> before = map;
  EXPECT_EQ(pullPush(map.data(), 8, 3, H, scratch), 0);
  EXPECT_EQ(map, before);
}

// 4 x 4 with three defined texels. Pull: the 2 x 2 level is {1, 5; hole, 8} (each the mean of its
// block's defined texels), not full, so a 1 x 1 level follows: (1 + 5 + 8) / 3. Push: the 2 x 2
// level's hole takes 14/3, then every hole of the finest level its block's 2 x 2 value.
TEST(PullPush, HolesTakeTheNearestCoarserLevelsMeanOfDefinedTexels) {
  std::vector<float> map = {1, H, 5, H,
                            H, H, H, H,
                            H, H, H, H,
                            H, H, H, 8}, scratch;
  EXPECT_EQ(pullPush(map.data(), 4, 8, H, scratch), 2);
  const float t = 14.0f / 3.0f;
  const std::vector<float> expected = {1, 1, 5, 5,
                                       1, 1, 5, 5,
                                       t, t, 8, 8,
                                       t, t, 8, 8};
  for (std::size_t i = 0; i < map.size(); ++i) EXPECT_FLOAT_EQ(map[i], expected[i]) << i;

  // One coarser level allowed: the empty 2 x 2 block cannot be filled and stays holes.
  std::vector<float> limited = {1, H, 5, H,
                                H, H, H, H,
                                H, H, H, H,
                                H, H, H, 8};
  EXPECT_EQ(pullPush(limited.data(), 4, 1, H, scratch), 1);
  const std::vector<float> expectedLimited = {1, 1, 5, 5,
                                              1, 1, 5, 5,
                                              H, H, 8, 8,
                                              H, H, 8, 8};
  EXPECT_EQ(limited, expectedLimited);
}

// A level with every texel defined ends the pull (the seed's note), however many are allowed.
TEST(PullPush, StopsAtTheFirstFullLevel) {
  std::vector<float> map(64, H), scratch;
  for (int y = 0; y < 8; y += 2)
    for (int x = 0; x < 8; x += 2) map[std::size_t(y) * 8 + x] = float(x + 10 * y);
  EXPECT_EQ(pullPush(map.data(), 8, 8, H, scratch), 1);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(map[std::size_t(y) * 8 + x], float((x & ~1) + 10 * (y & ~1)));
  EXPECT_THROW(pullPush(map.data(), 6, 2, H, scratch), Error);
}

TEST(Paraboloid, MapsDirectionsToTheDiskAndBack) {
  const ParaboloidFrame frame(glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f)));
  for (int i = 0; i < 200; ++i) {
    // Points of the disk out to 0.98 of its radius (the rim is the horizon, z = 0).
    const float r = 0.98f * float(i % 17) / 16.0f;
    const glm::vec2 uv(r * std::cos(0.37f * i), r * std::sin(0.37f * i));
    glm::vec2 back(0.0f);
    const glm::vec3 d = frame.direction(uv);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    ASSERT_TRUE(frame.project(d, back)) << i;
    EXPECT_NEAR(glm::length(back - uv), 0.0f, 1e-5f) << i;
  }
}

// Dense points give an imperfect map that matches the exact one (a ray per texel) wherever the
// exact map is smooth; sparse points match it less.
TEST(ImperfectShadowMaps, DensePointsAgreeWithExactShadowMapsAwayFromEdges) {
  const Scene scene = test::platesScene();
  const RayScene rays(scene);
  LightPathSettings paths;
  paths.paths = 24;
  const std::vector<Vpl> vpls = traceLightPaths(rays, paths);
  ASSERT_GT(vpls.size(), 10u);
  DepthMapSettings settings;
  settings.size = 32;
  VplDepthMaps exact;
  renderDepthMapsByRays(rays.embree(), vpls, settings, exact);
  const SurfacePointSampler sampler(scene);

  const auto agreement = [&](int points) {
    ImperfectSettings imperfect;
    imperfect.pointsPerVpl = points;
    VplDepthMaps ism;
    ImperfectCounts counts;
    splatImperfectShadowMaps(scene, sampler, vpls, settings, imperfect, ism, &counts);
    int smooth = 0, agree = 0;
    const int n = settings.size;
    for (std::size_t v = 0; v < vpls.size(); ++v)
      for (int y = 1; y + 1 < n; ++y)
        for (int x = 1; x + 1 < n; ++x) {
          const glm::vec2 uv = paraboloidTexelCentre(x, y, n);
          if (glm::length(uv) > 0.9f) continue;  // the rim: grazing directions
          const float e = exact.map(v)[std::size_t(y) * n + x];
          bool flat = std::isfinite(e);
          for (int dy = -1; dy <= 1 && flat; ++dy)
            for (int dx = -1; dx <= 1 && flat; ++dx) {
              const float f = exact.map(v)[std::size_t(y + dy) * n + x + dx];
              flat = std::isfinite(f) && std::abs(f - e) < 0.1f * e;
            }
          if (!flat) continue;
          ++smooth;
          agree += std::abs(ism.map(v)[std::size_t(y) * n + x] - e) < 0.1f * e;
        }
    const double fraction = double(agree) / smooth;
    std::cout << points << " points per VPL: " << 100.0 * fraction << "% of " << smooth
              << " smooth texels within 10% of the exact depth; holes "
              << 100.0 * counts.holesBefore / counts.diskTexels << "% before pull-push, "
              << 100.0 * counts.holesAfter / counts.diskTexels << "% after\n";
    return fraction;
  };
  const double dense = agreement(1 << 16), sparse = agreement(256);
  EXPECT_GT(dense, 0.97);
  EXPECT_LT(sparse, dense - 0.05);
}

}  // namespace
}  // namespace lpvlab
