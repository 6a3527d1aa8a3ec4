// Directional light views (framework/pipeline/light_views.h): the box around the scene, and the
// box that follows the camera, snapped to whole texels (thesis 6.2) or not.
#include "framework/pipeline/light_views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lpvlab {
namespace {

Light sun(const glm::vec3& direction) {
  Light light;
  light.name = "sun";
  light.type = LightType::Directional;
  light.direction = direction;
  light.intensity = 1.0f;
  return light;
}

// Where `world` falls in a view's map of `resolution` texels per side, in texels from its corner.
glm::dvec3 texelCoordinates(const GpuView& view, const glm::vec3& world, int resolution) {
  const glm::dvec4 clip = glm::dmat4(view.clipFromWorld) * glm::dvec4(glm::dvec3(world), 1.0);
  return {(clip.x * 0.5 + 0.5) * resolution, (clip.y * 0.5 + 0.5) * resolution, clip.z};
}

const Bounds kScene{{-1.0f, 0.0f, -2.0f}, {3.0f, 2.5f, 1.0f}};
const glm::vec3 kDirection = glm::normalize(glm::vec3(0.3f, -1.0f, 0.45f));
constexpr float kHalfWidth = 0.8f;
constexpr int kRsm = 64, kShadow = 256;

// The followed views for camera points scattered over the scene, snapped or not.
std::vector<GpuView> followedViews(bool snap, std::vector<glm::vec3>* centres = nullptr) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<GpuView> views;
  for (int i = 0; i < 64; ++i) {
    const glm::vec3 centre =
        kScene.min + glm::vec3(unit(random), unit(random), unit(random)) * kScene.extent();
    const DirectionalFollow follow{
        .centre = centre,
        .halfWidth = kHalfWidth,
        .texel = snap ? directionalSnapStep(kHalfWidth, kRsm, kShadow) : 0.0f};
    const LightViews built = buildLightViews({sun(kDirection)}, kScene, follow);
    EXPECT_EQ(built.views.size(), 1u);
    views.push_back(built.views.front());
    if (centres) centres->push_back(centre);
  }
  return views;
}

TEST(DirectionalViews, TheSnapStepIsWholeTexelsOfBothMaps) {
  for (auto [rsm, shadow] : {std::pair{256, 1024}, {64, 256}, {200, 300}, {7, 5}}) {
    const double step = directionalSnapStep(kHalfWidth, rsm, shadow);
    for (int resolution : {rsm, shadow}) {
      const double texels = step / (2.0 * kHalfWidth / resolution);
      EXPECT_NEAR(texels, std::round(texels), 1e-4) << rsm << " " << shadow;
      EXPECT_GE(std::round(texels), 1.0);
    }
  }
}

// Snapped, the texel grid stays put in the world: a fixed point falls at the same place within
// its texel of either map whatever the camera's position; unsnapped, it does not.
TEST(DirectionalViews, AFollowedSnappedViewKeepsTheTexelGridFixedInTheWorld) {
  const glm::vec3 points[] = {{0.2f, 1.0f, -0.5f}, {1.7f, 0.3f, 0.4f}, {-0.6f, 2.2f, -1.7f}};
  for (bool snap : {true, false}) {
    const std::vector<GpuView> views = followedViews(snap);
    for (int resolution : {kRsm, kShadow}) {
      for (const glm::vec3& point : points) {
        double lowest = 1.0, highest = -1.0;
        const glm::dvec3 first = texelCoordinates(views.front(), point, resolution);
        for (const GpuView& view : views) {
          // The offset from the first view, in texels, less its whole part: 0 when the grid
          // moved by whole texels (near 0 or 1 after rounding, hence the centring).
          const glm::dvec2 moved =
              glm::dvec2(texelCoordinates(view, point, resolution)) - glm::dvec2(first);
          for (double m : {moved.x, moved.y}) {
            const double fraction = m - std::round(m);
            lowest = std::min(lowest, fraction);
            highest = std::max(highest, fraction);
          }
        }
        if (snap) {
          EXPECT_LT(highest - lowest, 1e-3) << "texels of a " << resolution << " map";
        } else {
          EXPECT_GT(highest - lowest, 0.5) << "texels of a " << resolution << " map";
        }
      }
    }
  }
}

// The box holds the camera's point (moved by at most half a step each way across the light) and,
// along the light, the whole scene: every occluder of the box is in its depth range.
TEST(DirectionalViews, AFollowedViewHoldsItsPointAndTheSceneAlongTheLight) {
  for (bool snap : {true, false}) {
    std::vector<glm::vec3> centres;
    const std::vector<GpuView> views = followedViews(snap, &centres);
    const double halfStep = snap ? 0.5 * directionalSnapStep(kHalfWidth, kRsm, kShadow) : 0.0;
    for (std::size_t i = 0; i < views.size(); ++i) {
      EXPECT_FLOAT_EQ(views[i].params.x, 1.0f);
      EXPECT_FLOAT_EQ(views[i].params.y, 2.0f * kHalfWidth) << "the box's width";
      const glm::dvec3 centre = texelCoordinates(views[i], centres[i], 2);
      // In texels of a 2-texel map, the box's centre is at (1, 1); a metre is 1 / halfWidth.
      EXPECT_NEAR(centre.x, 1.0, halfStep / kHalfWidth + 1e-5);
      EXPECT_NEAR(centre.y, 1.0, halfStep / kHalfWidth + 1e-5);
      for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p = kScene.corner(corner);
        const double depth = texelCoordinates(views[i], p, 2).z;
        EXPECT_GT(depth, -1.0);
        EXPECT_LT(depth, 1.0);
      }
    }
  }
}

// Without following, the box is around the scene's bounding sphere: every corner of the bounds
// inside it, and its width the sphere's diameter.
TEST(DirectionalViews, TheSceneViewHoldsTheWholeScene) {
  const LightViews built = buildLightViews({sun(kDirection)}, kScene);
  ASSERT_EQ(built.views.size(), 1u);
  EXPECT_NEAR(built.views[0].params.y, glm::length(kScene.extent()), 1e-5);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 at = texelCoordinates(built.views[0], kScene.corner(corner), 2);
    for (double c : {at.x, at.y}) {
      EXPECT_GT(c, 0.0);
      EXPECT_LT(c, 2.0);
    }
    EXPECT_GT(at.z, -1.0);
    EXPECT_LT(at.z, 1.0);
  }
}

}  // namespace
}  // namespace lpvlab
