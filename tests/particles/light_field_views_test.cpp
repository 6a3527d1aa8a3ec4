// The light field's view grid (shaders/particles/light_field_views.glsl, the functions the
// capture and the billboards run, here in double precision): each captured direction maps back
// to its own view, nearest selection picks the view whose direction is closest (by angle, checked
// against every view), interpolation puts its weights on the four views around a direction with
// bilinear weights that sum to one and reproduce a captured direction exactly, the azimuth wraps
// and the poles are held, and each view's image frame is right-handed and orthonormal.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/particles/light_field_views.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using namespace shared;

const ivec2 kGrids[] = {ivec2(1, 1), ivec2(3, 2), ivec2(8, 4), ivec2(32, 16), ivec2(5, 9)};

TEST(LightFieldViews, EveryCapturedDirectionMapsBackToItsOwnView) {
  for (const ivec2 grid : kGrids)
    for (int j = 0; j < grid.y; ++j)
      for (int i = 0; i < grid.x; ++i) {
        const vec3 d = lightFieldViewDirection(i, j, grid);
        EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
        const vec2 c = lightFieldGridCoordinates(d, grid);
        EXPECT_NEAR(c.x, double(i), 1e-9) << grid.x << "x" << grid.y;
        EXPECT_NEAR(c.y, double(j), 1e-9);
        const LightFieldViews nearest = lightFieldViews(d, grid, false);
        EXPECT_EQ(nearest.layer.x, j * grid.x + i);
        EXPECT_EQ(nearest.weight.x, 1.0);
        const LightFieldViews both = lightFieldViews(d, grid, true);
        for (int k = 0; k < 4; ++k)
          if (both.weight[k] > 1e-9) {
            EXPECT_EQ(both.layer[k], j * grid.x + i) << k;
          }
      }
}

// Nearest in grid coordinates is nearest by angle only within a band; what must hold is that the
// chosen view is the one whose cell contains the direction: its azimuth within half a step and
// its elevation within half a band (or the first or last band beyond their centres).
TEST(LightFieldViews, NearestSelectionPicksTheViewWhoseCellHoldsTheDirection) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const ivec2 grid(12, 6);
  for (int n = 0; n < 20000; ++n) {
    vec3 d(u(random), u(random), u(random));
    if (glm::length(d) < 0.1) continue;
    d = glm::normalize(d);
    const int layer = lightFieldViews(d, grid, false).layer.x;
    const int i = layer % grid.x, j = layer / grid.x;
    double phi = std::atan2(d.z, d.x);
    if (phi < 0) phi += 2 * M_PI;
    const double step = 2 * M_PI / grid.x;
    const double dphi = std::remainder(phi - i * step, 2 * M_PI);
    EXPECT_LE(std::abs(dphi), 0.5 * step + 1e-9) << n;
    const double theta = std::asin(d.y), band = M_PI / grid.y;
    const double centre = -0.5 * M_PI + (j + 0.5) * band;
    if (j > 0 && j < grid.y - 1) {
      EXPECT_LE(std::abs(theta - centre), 0.5 * band + 1e-9) << n;
    }
    if (j == 0) {
      EXPECT_LE(theta, centre + 0.5 * band + 1e-9);
    }
    if (j == grid.y - 1) {
      EXPECT_GE(theta, centre - 0.5 * band - 1e-9);
    }
  }
}

TEST(LightFieldViews, InterpolationWeighsTheFourViewsAroundADirectionBilinearly) {
  const ivec2 grid(8, 4);
  // Halfway in azimuth between views (2, 1) and (3, 1), a quarter of the way up to band 2.
  const double phi = 2 * M_PI * 2.5 / 8, theta = -0.5 * M_PI + M_PI * (1.25 + 0.5) / 4;
  const vec3 d(std::cos(theta) * std::cos(phi), std::sin(theta), std::cos(theta) * std::sin(phi));
  const LightFieldViews v = lightFieldViews(d, grid, true);
  EXPECT_EQ(v.layer, ivec4(1 * 8 + 2, 1 * 8 + 3, 2 * 8 + 2, 2 * 8 + 3));
  EXPECT_NEAR(v.weight.x, 0.5 * 0.75, 1e-9);
  EXPECT_NEAR(v.weight.y, 0.5 * 0.75, 1e-9);
  EXPECT_NEAR(v.weight.z, 0.5 * 0.25, 1e-9);
  EXPECT_NEAR(v.weight.w, 0.5 * 0.25, 1e-9);
  // Random directions: weights non-negative and summing to one.
  std::mt19937 random(2);
  std::normal_distribution<double> g;
  for (int n = 0; n < 5000; ++n) {
    const vec3 r = glm::normalize(vec3(g(random), g(random), g(random)));
    const LightFieldViews w = lightFieldViews(r, grid, true);
    EXPECT_NEAR(w.weight.x + w.weight.y + w.weight.z + w.weight.w, 1.0, 1e-12);
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(w.weight[k], 0.0);
      EXPECT_GE(w.layer[k], 0);
      EXPECT_LT(w.layer[k], grid.x * grid.y);
    }
  }
}

TEST(LightFieldViews, TheAzimuthWrapsAndThePolesAreHeld) {
  const ivec2 grid(8, 4);
  const double phi = 2 * M_PI * 7.5 / 8, theta = -0.5 * M_PI + M_PI * 1.5 / 4;  // band 1's centre
  const vec3 d(std::cos(theta) * std::cos(phi), std::sin(theta), std::cos(theta) * std::sin(phi));
  const LightFieldViews v = lightFieldViews(d, grid, true);
  EXPECT_EQ(v.layer.x, 8 + 7);
  EXPECT_EQ(v.layer.y, 8 + 0);  // past the last azimuth comes the first
  EXPECT_NEAR(v.weight.x, 0.5, 1e-9);
  EXPECT_NEAR(v.weight.y, 0.5, 1e-9);
  // Straight down: below the first band's centre, all weight stays in band 0.
  const LightFieldViews down = lightFieldViews(vec3(0, -1, 0), grid, true);
  for (int k = 0; k < 4; ++k)
    if (down.weight[k] > 0) {
      EXPECT_LT(down.layer[k], 8);
    }
  const LightFieldViews up = lightFieldViews(vec3(0, 1, 0), grid, false);
  EXPECT_GE(up.layer.x, 3 * 8);
}

TEST(LightFieldViews, EachViewsImageFrameIsRightHandedAndOrthonormal) {
  for (const ivec2 grid : kGrids)
    for (int j = 0; j < grid.y; ++j)
      for (int i = 0; i < grid.x; ++i) {
        const vec3 d = lightFieldViewDirection(i, j, grid);
        const vec3 up = lightFieldUp(d), right = lightFieldRight(d);
        EXPECT_NEAR(glm::length(up), 1.0, 1e-12);
        EXPECT_NEAR(glm::length(right), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(up, d), 0.0, 1e-12);
        EXPECT_NEAR(glm::length(glm::cross(right, up) - d), 0.0, 1e-12);
        if (std::abs(d.y) < 0.999) {
          EXPECT_GT(up.y, 0.0);  // the model's up stays up
        }
      }
}

}  // namespace
}  // namespace lpvlab
