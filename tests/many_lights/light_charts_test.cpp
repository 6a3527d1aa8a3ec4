// Incremental instant radiosity's light charts (framework/many_lights/light_charts.h), in both
// placements: a disk point's ray projects back to the same point; the power a chart's disk holds
// is the light's (instant radiosity's closed-form lightPower); on a power chart the power within
// radius r is pi r^2 times its constant density, by an independent quadrature of the falloff; and
// a VPL set placed by power around a point light gives its VPLs more equal shares of the light
// than one placed evenly in the projection.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "framework/many_lights/incremental_vpls.h"
#include "framework/many_lights/light_charts.h"
#include "framework/many_lights/light_paths.h"
#include "framework/math/shared.h"
#include "reference/test_scenes.h"

namespace lpvlab {
namespace {

PunctualLight pointLight() {
  return {.type = LightType::Point, .position = glm::vec3(0.1f, 0.2f, -0.3f),
          .direction = glm::vec3(0.0f), .radiant = glm::vec3(2.0f, 1.0f, 0.5f),
          .cosInner = -1.0, .cosOuter = -1.0};
}

PunctualLight spotLight() {
  return {.type = LightType::Spot, .position = glm::vec3(0.0f, 1.0f, 0.0f),
          .direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f)), .radiant = glm::vec3(3.0f),
          .cosInner = std::cos(0.3), .cosOuter = std::cos(0.7)};
}

const Bounds kScene{glm::vec3(-2.0f), glm::vec3(2.0f)};

// The power over the whole disk by the midpoint rule on a grid of n x n cells.
glm::dvec3 diskPower(const LightChart& chart, int n) {
  glm::dvec3 sum(0.0);
  const double cell = 2.0 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const glm::vec2 uv(float(-1.0 + (i + 0.5) * cell), float(-1.0 + (j + 0.5) * cell));
      if (glm::dot(uv, uv) <= 1.0f) sum += glm::dvec3(chart.powerDensity(uv)) * cell * cell;
    }
  return sum;
}

TEST(LightCharts, RaysProjectBackToTheirDiskPointInBothPlacements) {
  for (const ChartPlacement placement : {ChartPlacement::Projection, ChartPlacement::Power})
    for (const PunctualLight& light : {pointLight(), spotLight()})
      for (const LightChart& chart : lightCharts({light}, kScene, placement))
        for (const glm::vec2 uv : {glm::vec2(0.0f), glm::vec2(0.3f, -0.2f), glm::vec2(-0.7f, 0.5f),
                                   glm::vec2(0.0f, 0.999f)}) {
          glm::vec3 start, direction;
          chart.ray(uv, start, direction);
          EXPECT_NEAR(glm::length(direction), 1.0f, 1e-5f);
          glm::vec2 back;
          ASSERT_TRUE(chart.project(start + 1.7f * direction, back));
          EXPECT_NEAR(back.x, uv.x, 2e-4f);
          EXPECT_NEAR(back.y, uv.y, 2e-4f);
        }
}

TEST(LightCharts, EachPlacementsDiskHoldsTheLightsPower) {
  for (const PunctualLight& light : {pointLight(), spotLight()}) {
    const glm::dvec3 expected = lightPower(light, 1.0);
    for (const ChartPlacement placement : {ChartPlacement::Projection, ChartPlacement::Power}) {
      glm::dvec3 total(0.0);
      for (const LightChart& chart : lightCharts({light}, kScene, placement)) total += diskPower(chart, 800);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(total[c], expected[c], 3e-3 * expected[c])
            << (placement == ChartPlacement::Power ? "power" : "projection") << " chart, channel " << c;
    }
  }
}

TEST(LightCharts, APowerChartsDiskAreaIsItsLightsPower) {
  // Point light: the power within angle theta is 2 pi I (1 - cos theta), so |uv|^2 = 1 - cos theta.
  for (const LightChart& chart : lightCharts({pointLight()}, kScene, ChartPlacement::Power))
    for (const float r : {0.1f, 0.5f, 0.9f}) {
      glm::vec3 start, direction;
      chart.ray(glm::vec2(r, 0.0f), start, direction);
      EXPECT_NEAR(glm::dot(direction, chart.axis), 1.0f - r * r, 1e-5f);
    }
  // Spot: the falloff integrated by Simpson's rule from cos(theta) to 1, over the whole cone's.
  const PunctualLight spot = spotLight();
  const LightChart chart = lightCharts({spot}, kScene, ChartPlacement::Power).front();
  const auto within = [&](double cosTheta) {
    constexpr int kSteps = 20000;
    const double h = (1.0 - cosTheta) / kSteps;
    double sum = 0.0;
    for (int k = 0; k <= kSteps; ++k) {
      const double f = shared::spotFalloff(cosTheta + k * h, spot.cosInner, spot.cosOuter);
      sum += f * (k == 0 || k == kSteps ? 1.0 : k % 2 ? 4.0 : 2.0);
    }
    return sum * h / 3.0;
  };
  const double whole = within(spot.cosOuter);
  for (const float r : {0.2f, 0.6f, 0.85f}) {
    glm::vec3 start, direction;
    chart.ray(glm::vec2(0.0f, r), start, direction);
    EXPECT_NEAR(within(double(glm::dot(direction, chart.axis))) / whole, double(r) * r, 2e-4);
  }
  EXPECT_NEAR(double(chart.powerDensity(glm::vec2(0.3f)).r) * M_PI, 2.0 * M_PI * 3.0 * whole, 1e-4 * whole);
}

// A point light at the centre of a closed grey sphere: every VPL's flux is its cell's power times
// the albedo. Spread evenly by power, the VPLs' shares differ only by the cells' irregularity (the
// cells on a disk's rim are cut by it); in the projection they differ also by the paraboloid's
// density, 4x from pole to rim.
TEST(LightCharts, PlacingByPowerGivesTheVplsEqualShares) {
  Scene scene;
  scene.source = "test:grey sphere";
  Material grey;
  grey.name = "grey";
  grey.baseColor = glm::vec3(0.5f);
  scene.materials.push_back(grey);
  scene.meshes.push_back(testing::inwardSphere(0, 2.0f, 48, 96));
  Light light;
  light.name = "bulb";
  light.type = LightType::Point;
  light.position = glm::vec3(0.0f, 0.05f, 0.0f);
  light.intensity = 1.0f;
  scene.lights.push_back(light);
  const RayScene rays(scene);

  const auto spread = [&](ChartPlacement placement, double& total) {
    IncrementalSettings settings;
    settings.vpls = 200;
    settings.placement = placement;
    IncrementalVpls set(settings);
    IncrementalCounts counts;
    const std::vector<Vpl>& vpls = set.update(rays, counts);
    double sum = 0.0, squares = 0.0;
    for (const Vpl& vpl : vpls) sum += vpl.flux.r, squares += double(vpl.flux.r) * vpl.flux.r;
    const double n = double(vpls.size()), mean = sum / n;
    total = sum / 0.5;  // the cells' power
    return std::sqrt(std::max(squares / n - mean * mean, 0.0)) / mean;
  };
  double projectionTotal = 0.0, powerTotal = 0.0;
  const double projection = spread(ChartPlacement::Projection, projectionTotal);
  const double power = spread(ChartPlacement::Power, powerTotal);
  std::cout << "VPL flux, relative standard deviation: projection " << projection << ", power "
            << power << "; power over the VPLs " << projectionTotal << " and " << powerTotal
            << " (4 pi I = " << 4.0 * M_PI << ")\n";
  EXPECT_NEAR(projectionTotal, 4.0 * M_PI, 0.01 * 4.0 * M_PI);
  EXPECT_NEAR(powerTotal, 4.0 * M_PI, 0.01 * 4.0 * M_PI);
  EXPECT_LT(power, 0.6 * projection);  // measured 0.25 against 0.47
}

}  // namespace
}  // namespace lpvlab
