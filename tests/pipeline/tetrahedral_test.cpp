// Tetrahedral propagation ("tetrahedral": shaders/propagation/tetrahedral_*.comp) through the
// whole strategy on hand-made cubic grids:
//   - the GPU (split, gather steps, merge) against the double-precision C++ of the same shared
//     GLSL (tetrahedral_lattice.glsl) on random grids;
//   - resampling cubic -> lattice -> cubic conserves flux (zero steps);
//   - flux per step against the normalisation: the 12 far faces of a cell's four neighbours
//     tile the sphere, so a step from an isotropic source sends exactly its flux; the clamp can
//     only add, by at most the factor computed below; until light reaches the grid's boundary
//     (the closed shell here) nothing is lost, and `accumulated` is the injected light plus
//     every step's;
//   - a single VPL in the middle keeps the lattice's symmetries (it keeps all 48 of the cube's
//     about a cube centre: tests/math/tetrahedral_lattice_test.cpp).

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "framework/math/tetrahedral_solid_angles.h"
#include "propagation_rig.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using namespace test;
using Cells = std::vector<double>;  // the lattice, grid.glsl's layout over tetSlotCount slots

// The tetrahedral strategy and its light grid of cubes; run: load current and accumulated, then
// propagate.
PropagationRig tetrahedralRig(const glm::ivec3& resolution, int iterations) {
  return PropagationRig("tetrahedral", resolution, iterationsTable(iterations));
}
void run(PropagationRig& rig, const Grid& current, const Grid& accumulated) {
  rig.load(current, accumulated);
  rig.propagate();
}
void run(PropagationRig& rig, const Grid& injected) { run(rig, injected, injected); }

std::size_t slotAt(const glm::ivec3& res, const glm::ivec4& tet, int channel, int k) {
  return std::size_t(shared::coefficientIndex(channel, k, kCoefficients,
                                              shared::tetSlot(tet, res), shared::tetSlotCount(res)));
}

// Every tetrahedral cell of the lattice inside the grid.
void forEachTet(const glm::ivec3& res, const std::function<void(const glm::ivec4&)>& f) {
  forEachCell(res, [&](const glm::ivec3& c) {
    for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
      const glm::ivec4 tet{c.x, c.y, c.z, code};
      if (shared::tetInside(tet, res)) f(tet);
    }
  });
}

glm::dvec4 coefficientsOf(const Cells& cells, const glm::ivec3& res, const glm::ivec4& tet, int channel) {
  glm::dvec4 c;
  for (int k = 0; k < kCoefficients; ++k) c[k] = cells[slotAt(res, tet, channel, k)];
  return c;
}

// ---- the double-precision reference of split, gather and merge --------------------------------

Cells split(const Grid& g, const glm::ivec3& res) {
  Cells cells(std::size_t(3) * kCoefficients * shared::tetSlotCount(res), 0.0);
  forEachTet(res, [&](const glm::ivec4& tet) {
    const glm::ivec3 lower{tet.x, tet.y, tet.z};
    const glm::ivec3 upper = lower + shared::tetUnitOffset(shared::tetAxis(tet.w));
    for (int channel = 0; channel < 3; ++channel) {
      const glm::dvec4 c = shared::tetSplitWeight(lower, res) * cellOf(g, res, lower, channel) +
                           shared::tetSplitWeight(upper, res) * cellOf(g, res, upper, channel);
      for (int k = 0; k < kCoefficients; ++k) cells[slotAt(res, tet, channel, k)] = c[k];
    }
  });
  return cells;
}

const TetrahedralFaceSolidAngles kAngles = tetrahedralFaceSolidAngles();

Cells step(const Cells& source, const glm::ivec3& res) {
  Cells target(source.size(), 0.0);
  forEachTet(res, [&](const glm::ivec4& tet) {
    for (int face = 0; face < shared::TET_FACES; ++face) {
      const glm::ivec4 n = shared::tetNeighbour(tet, face);
      if (!shared::tetInside(n, res)) continue;
      for (int channel = 0; channel < 3; ++channel) {
        const glm::dvec4 got = shared::tetReceiveFrom(coefficientsOf(source, res, n, channel), tet.w,
                                                      face, kAngles.smallFace, kAngles.largeFace);
        for (int k = 0; k < kCoefficients; ++k) target[slotAt(res, tet, channel, k)] += got[k];
      }
    }
  });
  return target;
}

Grid merge(const Cells& cells, const glm::ivec3& res) {
  std::vector<double> sum(std::size_t(3) * kCoefficients * test::cells(res), 0.0);
  forEachTet(res, [&](const glm::ivec4& tet) {
    const glm::ivec3 lower{tet.x, tet.y, tet.z};
    const glm::ivec3 upper = lower + shared::tetUnitOffset(shared::tetAxis(tet.w));
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < kCoefficients; ++k) {
        const double v = shared::TET_MERGE_WEIGHT * cells[slotAt(res, tet, channel, k)];
        sum[at(res, lower, channel, k)] += v;
        sum[at(res, upper, channel, k)] += v;
      }
  });
  return Grid(sum.begin(), sum.end());
}

// ---- the clamp's gain -----------------------------------------------------------------------------

// The largest factor by which one step can multiply a cell's flux, over cells holding one
// clamped-cosine lobe Phi / pi * cosLobe(n) (n sampled densely, every cell orientation); a
// non-negative sum of lobes gains at most as much. Without the clamp it is exactly 1.
double maxStepGain() {
  double gain = 1.0;
  const int n = 4000;
  for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
    const glm::ivec4 source{0, 0, 0, code};
    for (int i = 0; i < n; ++i) {
      const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
      const double phi = M_PI * (3.0 - std::sqrt(5.0)) * i;
      const glm::dvec4 lobe = shared::shCosineLobe({r * std::cos(phi), r * std::sin(phi), z}) / M_PI;
      double out = 0.0;
      for (int face = 0; face < shared::TET_FACES; ++face) {
        const glm::ivec4 target = shared::tetNeighbour(source, face);
        for (int back = 0; back < shared::TET_FACES; ++back)
          if (shared::tetNeighbour(target, back) == source)
            out += shared::shIntegral(shared::tetReceiveFrom(lobe, target.w, back, kAngles.smallFace,
                                                             kAngles.largeFace));
      }
      gain = std::max(gain, out);
    }
  }
  return gain;
}

// ---- a. the kernels against the C++ ------------------------------------------------------------

TEST(TetrahedralPropagation, GpuMatchesTheSharedCppOnRandomGrids) {
  const glm::ivec3 res{5, 4, 3};  // not multiples of the work group, nor a cube; many boundary cells
  const int iterations = 3;
  const std::size_t n = std::size_t(3) * kCoefficients * cells(res);
  std::mt19937 random(2024);
  const Grid current = randomFloats(n, random), accumulated = randomFloats(n, random);

  PropagationRig rig = tetrahedralRig(res, iterations);
  run(rig, current, accumulated);
  const Grid gpuCurrent = rig.current(), gpuAccumulated = rig.accumulated();

  Cells cells = split(current, res), sum(cells.size(), 0.0);
  for (int i = 0; i < iterations; ++i) {
    cells = step(cells, res);
    for (std::size_t j = 0; j < sum.size(); ++j) sum[j] += cells[j];
  }
  const Grid expectedCurrent = merge(cells, res), merged = merge(sum, res);
  const double tolerance = 1e-5 * std::max(maxAbs(expectedCurrent), maxAbs(merged));
  ASSERT_GT(maxAbs(expectedCurrent), 1e-3);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_NEAR(gpuCurrent[i], expectedCurrent[i], tolerance) << "current float " << i;
    ASSERT_NEAR(gpuAccumulated[i], accumulated[i] + merged[i], tolerance) << "accumulated float " << i;
  }
}

// ---- b. resampling and the normalisation ------------------------------------------------------

TEST(TetrahedralPropagation, ResamplingConservesFlux) {
  const glm::ivec3 res{4, 3, 5};
  const std::size_t n = std::size_t(3) * kCoefficients * cells(res);
  std::mt19937 random(99);
  const Grid g = randomFloats(n, random);
  PropagationRig rig = tetrahedralRig(res, 0);
  run(rig, g);
  EXPECT_EQ(rig.accumulated(), g) << "no steps add nothing";
  const Grid resampled = rig.current();
  EXPECT_NEAR(flux(resampled, res), flux(g, res), 1e-5 * maxAbs(g) * double(n));
  double differs = 0.0;  // the round trip smooths (half the cube, half its face neighbours)
  for (std::size_t i = 0; i < n; ++i) differs = std::max(differs, double(std::abs(resampled[i] - g[i])));
  EXPECT_GT(differs, 0.1);
  // Every cube alone, corner ones included, keeps its flux.
  for (const glm::ivec3& cube : {glm::ivec3(0, 0, 0), glm::ivec3(3, 2, 4), glm::ivec3(1, 1, 2)}) {
    const Grid one = pointSource(res, cube, true);
    run(rig, one);
    EXPECT_NEAR(flux(rig.current(), res), injectedFlux(), 1e-6 * injectedFlux());
  }
}

void fluxPerStep(bool isotropic) {
  const glm::ivec3 res{13, 13, 13};
  const glm::ivec3 centre{6, 6, 6};
  const int steps = 8;  // light moves 0.35 cubes per step (plus one cube of resampling each way):
                        // it stays well inside until then
  const double phi = injectedFlux(), gMax = maxStepGain();
  const Grid injected = pointSource(res, centre, isotropic);
  std::cout << "[ tetrahedral ] " << (isotropic ? "isotropic" : "+z cosine-lobe")
            << " source; largest clamp gain per step " << gMax << "\n";
  double before = phi, stepsFlux = 0.0;
  for (int k = 1; k <= steps; ++k) {
    PropagationRig rig = tetrahedralRig(res, k);
    run(rig, injected);
    const double now = flux(rig.current(), res), accumulated = flux(rig.accumulated(), res);
    std::cout << "[ tetrahedral ] step " << k << ": flux " << now << " W (" << now / phi
              << " of injected), accumulated " << accumulated << " W\n";
    if (isotropic && k == 1) {
      EXPECT_NEAR(now, phi, 1e-5 * phi) << "the far faces tile the sphere";
    }
    EXPECT_GE(now, before * (1.0 - 1e-5)) << "step " << k << ": nothing leaves the grid yet";
    EXPECT_LE(now, before * gMax * (1.0 + 1e-5)) << "step " << k;
    stepsFlux += now;
    EXPECT_NEAR(accumulated, phi + stepsFlux, 1e-5 * (phi + stepsFlux)) << "step " << k;
    before = now;
  }
  EXPECT_GT(gMax, 1.0) << "the clamp adds for some lobe";
}

TEST(TetrahedralPropagation, FluxPerStepFromAnIsotropicSource) { fluxPerStep(true); }
TEST(TetrahedralPropagation, FluxPerStepFromALobe) { fluxPerStep(false); }

TEST(TetrahedralPropagation, LightLeavesASmallGrid) {
  const glm::ivec3 res{5, 5, 5};
  PropagationRig rig = tetrahedralRig(res, 300);
  run(rig, pointSource(res, {2, 2, 2}, false));
  const double now = flux(rig.current(), res);
  ASSERT_TRUE(std::isfinite(now));
  EXPECT_GE(now, 0.0);
  EXPECT_LT(now, 1e-4 * injectedFlux());
}

// ---- c. symmetry -------------------------------------------------------------------------------

// The cube's symmetries about the centre cube's centre (grid_test_support.h).
const glm::ivec3 kRes11{11, 11, 11};
const glm::ivec3 kCentre11{5, 5, 5};

TEST(TetrahedralPropagation, IsotropicVplKeepsTheCubesSymmetries) {
  PropagationRig rig = tetrahedralRig(kRes11, 7);
  run(rig, pointSource(kRes11, kCentre11, true));
  for (const Grid& g : {rig.current(), rig.accumulated()}) {
    ASSERT_GT(maxAbs(g), 0.0);
    for (const Symmetry& s : {kMirrorX, kMirrorY, kMirrorZ, kSwapXY, kRotateZ, kRotateX, kRotateXYZ})
      EXPECT_LE(asymmetry(g, kRes11, kCentre11, s), 1e-5 * maxAbs(g)) << s.name;
  }
}

TEST(TetrahedralPropagation, LobeAlongZKeepsTheSymmetriesAboutZ) {
  PropagationRig rig = tetrahedralRig(kRes11, 7);
  run(rig, pointSource(kRes11, kCentre11, false));
  for (const Grid& g : {rig.current(), rig.accumulated()}) {
    for (const Symmetry& s : {kMirrorX, kMirrorY, kSwapXY, kRotateZ})
      EXPECT_LE(asymmetry(g, kRes11, kCentre11, s), 1e-5 * maxAbs(g)) << s.name;
    EXPECT_GT(asymmetry(g, kRes11, kCentre11, kMirrorZ), 0.1 * maxAbs(g)) << "the light goes up";
  }
}

}  // namespace
}  // namespace lpvlab
