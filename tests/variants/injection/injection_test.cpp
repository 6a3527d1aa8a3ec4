// Injection end to end on the built-in Cornell box: the reflective shadow maps' flux against an
// independent estimate from the spot's emission, and the light grid's flux after injection
// against the RSM's (rsm_vpl adds every texel's whole flux to exactly one cell, or drops it when
// the cell is outside the grid).

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lpv_support.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "framework/scene/scene_loader.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

// Small output; the shadow maps do not matter for injection, so they are small too.
std::vector<std::string> baseOverrides() {
  return {"output.width=128", "output.height=128", "light_maps.shadow_resolution=128",
          "timing.warmup=0", "timing.repeats=1"};
}

InjectionBalance measure(const std::vector<std::string>& extraOverrides) {
  test::glTestContext();
  std::vector<std::string> overrides = baseOverrides();
  overrides.insert(overrides.end(), extraOverrides.begin(), extraOverrides.end());
  Experiment e = loadExperiment("", overrides);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();  // renders the RSMs that measureInjection reads
  return test::lpvOf(pipeline).measureInjection();
}

// The built-in box's one light: the spot under the ceiling.
const Light& cornellSpot(const Scene& scene) {
  EXPECT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights.at(0).type, LightType::Spot);
  return scene.lights.at(0);
}

// integral over the sphere of spotFalloff(cos angle to the axis) = 2 pi integral_{-1}^{1} f(t) dt,
// midpoint rule in t = cos(angle), split at the inner and outer cone where f has kinks.
double spotFalloffSolidAngle(const Light& light) {
  const double cosInner = std::cos(double(light.innerConeAngle));
  const double cosOuter = std::cos(double(light.outerConeAngle));
  const double breaks[] = {-1.0, cosOuter, cosInner, 1.0};
  double sum = 0.0;
  const int n = 200000;
  for (int piece = 0; piece < 3; ++piece) {
    const double a = breaks[piece], b = breaks[piece + 1], h = (b - a) / n;
    for (int i = 0; i < n; ++i)
      sum += h * shared::spotFalloff(a + (i + 0.5) * h, cosInner, cosOuter);
  }
  return 2.0 * M_PI * sum;
}

// The flux the surfaces first hit by the spot reflect, summed over RGB: the integral over the
// cone of I(w) * albedo(first hit along w), by ray casting the scene's triangles (an estimate
// independent of rasterisation, cube-face views and texel solid angles).
double raycastReflectedFlux(const Scene& scene, const Light& light) {
  const test::SceneRaycaster raycaster(scene);
  const glm::dvec3 axis = glm::normalize(glm::dvec3(light.direction));
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(axis, helper)), e2 = glm::cross(axis, e1);
  const double cosInner = std::cos(double(light.innerConeAngle));
  const double cosOuter = std::cos(double(light.outerConeAngle));
  const glm::dvec3 intensity = glm::dvec3(light.color) * double(light.intensity);
  const int nt = 300, nphi = 600;  // midpoint rule in cos(angle) and azimuth
  const double dt = (1.0 - cosOuter) / nt, dphi = 2.0 * M_PI / nphi;
  double flux = 0.0;
  for (int i = 0; i < nt; ++i) {
    const double t = cosOuter + (i + 0.5) * dt, r = std::sqrt(1.0 - t * t);
    const double falloff = shared::spotFalloff(t, cosInner, cosOuter);
    for (int j = 0; j < nphi; ++j) {
      const double phi = (j + 0.5) * dphi;
      const glm::dvec3 w = t * axis + r * (std::cos(phi) * e1 + std::sin(phi) * e2);
      const auto hit = raycaster.cast(glm::dvec3(light.position), w);
      if (!hit) continue;  // out through the open front of the box
      const glm::dvec3 albedo(raycaster.material(*hit).baseColor);
      flux += glm::dot(albedo, intensity) * falloff * dt * dphi;
    }
  }
  return flux;
}

TEST(Injection, GridHoldsTheRsmFluxAndTheRsmFluxMatchesTheSpot) {
  const InjectionBalance balance = measure({});
  std::cout << "[ injection ] rsm flux " << balance.rsmFlux << " W, grid flux " << balance.gridFlux
            << " W\n";
  EXPECT_GT(balance.rsmFlux, 0.0);
  EXPECT_GT(balance.gridFlux, 0.0);
  // The default grid covers the box with a margin: every texel's flux lands in the grid.
  EXPECT_NEAR(balance.gridFlux, balance.rsmFlux, 1e-4 * balance.rsmFlux);

  // Upper bound: what the spot emits (per channel), times the largest albedo of that channel.
  const Scene scene = makeCornellBox();
  const Light& spot = cornellSpot(scene);
  const double coneSolidAngle = spotFalloffSolidAngle(spot);
  // Sanity of the quadrature: the cone lies between the inner and the outer half-angle's caps.
  EXPECT_GT(coneSolidAngle, 2.0 * M_PI * (1.0 - std::cos(double(spot.innerConeAngle))));
  EXPECT_LT(coneSolidAngle, 2.0 * M_PI * (1.0 - std::cos(double(spot.outerConeAngle))));
  glm::dvec3 maxAlbedo(0.0), minAlbedo(1.0);
  for (const Material& m : scene.materials) {
    maxAlbedo = glm::max(maxAlbedo, glm::dvec3(m.baseColor));
    minAlbedo = glm::min(minAlbedo, glm::dvec3(m.baseColor));
  }
  const glm::dvec3 emitted = glm::dvec3(spot.color) * double(spot.intensity) * coneSolidAngle;
  const double upper = glm::dot(maxAlbedo, emitted);
  std::cout << "[ injection ] spot emits " << emitted.x + emitted.y + emitted.z
            << " W into its cone; reflected flux bound " << upper << " W\n";
  EXPECT_LE(balance.rsmFlux, upper * (1.0 + 1e-4));
  // Loose lower bound: most of the box is white, and most of the cone meets it.
  EXPECT_GT(balance.rsmFlux, 0.3 * upper);

  // The independent estimate: the cone ray cast against the triangles. The RSM samples the same
  // integral at texel centres of 256^2-texel cube faces; edges (the open front, the blocks)
  // make the two differ by about 0.1%.
  const double raycast = raycastReflectedFlux(scene, spot);
  std::cout << "[ injection ] ray-cast reflected flux " << raycast << " W (RSM / ray cast = "
            << balance.rsmFlux / raycast << ")\n";
  EXPECT_NEAR(balance.rsmFlux, raycast, 0.005 * raycast);
}

TEST(Injection, LightOutsideAFixedGridIsDroppedAndTwoHalvesAddUpToTheWhole) {
  // Three fixed placements on one lattice of 5 cm cells: the whole box with a margin, the half
  // x < 0.3 m and the half x >= 0.3 m. Every VPL lands in exactly one cell of the whole grid and
  // of exactly one of the halves.
  const InjectionBalance whole = measure({"grid.origin=[-0.1, -0.1, -0.1]", "grid.cell_size=0.05",
                                          "grid.cells=[15, 15, 15]"});
  const InjectionBalance low = measure({"grid.origin=[-0.1, -0.1, -0.1]", "grid.cell_size=0.05",
                                        "grid.cells=[8, 15, 15]"});
  const InjectionBalance high = measure({"grid.origin=[0.3, -0.1, -0.1]", "grid.cell_size=0.05",
                                         "grid.cells=[7, 15, 15]"});
  std::cout << "[ injection ] fixed grids: whole " << whole.gridFlux << " W, x < 0.3 m "
            << low.gridFlux << " W, x >= 0.3 m " << high.gridFlux << " W (RSM " << whole.rsmFlux
            << " W)\n";
  EXPECT_NEAR(whole.gridFlux, whole.rsmFlux, 1e-4 * whole.rsmFlux);
  for (const InjectionBalance* half : {&low, &high}) {
    EXPECT_NEAR(half->rsmFlux, whole.rsmFlux, 1e-6 * whole.rsmFlux);  // same RSM every time
    EXPECT_GT(half->gridFlux, 0.1 * half->rsmFlux);  // each half of the box is lit
    EXPECT_LT(half->gridFlux, 0.9 * half->rsmFlux);  // and the other half is dropped
  }
  EXPECT_NEAR(low.gridFlux + high.gridFlux, whole.gridFlux, 1e-4 * whole.gridFlux);
}

}  // namespace
}  // namespace lpvlab
