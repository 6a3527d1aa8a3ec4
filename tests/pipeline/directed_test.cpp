// Directed propagation ("directed", shaders/propagation/directed_*.comp) on hand-made grids:
//   - the GPU's dilation and gather are the double-precision C++ of the same shared GLSL
//     (directed_faces.glsl), over two iterations of random light and a sparse random normal grid,
//     without and with a random geometry volume (occluding from the second iteration on);
//   - the normalisation: 1 / G(n) is what one unnormalised step keeps of a lobe about n, which
//     for an axis normal is written out here face by face; with G, a VPL's lobe propagating among
//     the normals dilated from its own keeps its flux at every iteration (the flux within a
//     closed shell changes only by what crosses it), where the unnormalised step would keep r^k;
//   - the point of the method: a VPL on a floor facing +y lights nothing below the floor, where
//     standard propagation does.

#include <cmath>
#include <functional>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "framework/math/solid_angle.h"
#include "propagation_rig.h"

// The GV lookup (propagation_rig.h) reads the global `gvBlocking`; the model sets it.
LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/directed_faces.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using namespace test;

const CubeFaceSolidAngles& angles() {
  static const CubeFaceSolidAngles a = cubeFaceSolidAngles();
  return a;
}

glm::dvec4 normalOf(const std::vector<float>& n, const glm::ivec3& res, const glm::ivec3& cell) {
  const std::size_t i = std::size_t(4) * shared::cellIndex(cell, res);
  return {n[i], n[i + 1], n[i + 2], n[i + 3]};
}

// ---- the double-precision model: the shared GLSL, dilated and gathered as the kernels do -------

std::vector<float> dilate(const std::vector<float>& normals, const glm::ivec3& res) {
  std::vector<float> out(normals.size());
  forEachCell(res, [&](const glm::ivec3& c) {
    glm::dvec3 sum(0.0);
    for (const glm::ivec3& d : kAxes)
      if (shared::cellInside(c + d, res)) sum += shared::directedUnitNormal(normalOf(normals, res, c + d));
    const glm::dvec4 v = shared::directedDilated(normalOf(normals, res, c), sum);
    for (int k = 0; k < 4; ++k) out[std::size_t(4) * shared::cellIndex(c, res) + k] = float(v[k]);
  });
  return out;
}

// What `cell`'s neighbour at cell - d sends it along d, per channel; `occluded`: through the GV
// in shared::gvBlocking.
glm::dvec4 received(const Grid& g, const std::vector<float>& normals, const glm::ivec3& res,
                    const glm::ivec3& cell, const glm::ivec3& d, int channel, bool occluded = false) {
  const glm::dvec4 stored = normalOf(normals, res, cell);
  const glm::dvec3 n = shared::directedUnitNormal(stored);
  const double gain = shared::directedGainOf(stored, angles().farFace, angles().sideFace);
  const glm::dvec4 c = cellOf(g, res, cell - d, channel);
  const glm::dvec3 axis(d), sourceCentre = glm::dvec3(cell - d) + 0.5;
  glm::dvec4 sum(0.0);
  for (int f = 0; f < shared::STANDARD_FACES; ++f) {
    const glm::dvec3 w = shared::standardFaceDirection(axis, f);
    const double transmittance =
        occluded ? shared::gvTransmittance(
                       shared::gvBlockingAt(shared::standardFaceCrossing(sourceCentre, axis, f), res + 1), w)
                 : 1.0;
    sum += shared::directedThroughFace(
        c, w, shared::standardFaceNormal(axis, f),
        shared::standardFaceSolidAngle(f, angles().farFace, angles().sideFace), transmittance, n, gain);
  }
  return sum;
}

// One gather step: the new light, added to `accumulated`.
Grid step(const Grid& g, const std::vector<float>& normals, const glm::ivec3& res, Grid& accumulated,
          bool occluded = false) {
  Grid out(g.size(), 0.0f);
  forEachCell(res, [&](const glm::ivec3& cell) {
    for (int channel = 0; channel < 3; ++channel) {
      glm::dvec4 sum(0.0);
      for (const glm::ivec3& d : kAxes)
        if (shared::cellInside(cell - d, res))
          sum += received(g, normals, res, cell, d, channel, occluded);
      for (int k = 0; k < kCoefficients; ++k) {
        out[at(res, cell, channel, k)] = float(sum[k]);
        accumulated[at(res, cell, channel, k)] += float(sum[k]);
      }
    }
  });
  return out;
}

// The normal grid with one cell holding a VPL's normal: Phi n, Phi (Phi its flux over RGB).
std::vector<float> vplNormals(const glm::ivec3& res, const glm::ivec3& cell, const glm::dvec3& n) {
  std::vector<float> normals(std::size_t(4) * cells(res), 0.0f);
  const double phi = injectedFlux();
  const std::size_t i = std::size_t(4) * shared::cellIndex(cell, res);
  for (int k = 0; k < 3; ++k) normals[i + k] = float(phi * n[k]);
  normals[i + 3] = float(phi);
  return normals;
}

// ---- a. the kernels against the C++ ------------------------------------------------------------

// With a GV, iteration 0 unoccluded and iteration 1 through it (firstOccludedIteration = 1).
void twoIterationsMatchTheCpp(bool withGv) {
  const glm::ivec3 res{6, 5, 4};  // not multiples of the 4^3 work group, nor a cube
  std::mt19937 random(4242);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  const std::size_t n = std::size_t(3) * kCoefficients * cells(res);
  const Grid current = randomFloats(n, random), accumulated = randomFloats(n, random);
  std::vector<float> normals(std::size_t(4) * cells(res), 0.0f);
  int withNormal = 0;
  for (std::size_t i = 0; i < normals.size(); i += 4)
    if (uniform(random) > 0.6f) {  // a sparse grid, so that dilation has work at both steps
      ++withNormal;
      for (int k = 0; k < 3; ++k) normals[i + k] = uniform(random);
      normals[i + 3] = 1.0f;
    }
  ASSERT_GT(withNormal, 3);

  PropagationRig rig("directed", res, iterationsTable(2), 1, withGv);
  rig.load(current, accumulated);
  rig.loadNormals(normals);
  if (withGv) {
    // Blocking potential of random surfels: c0 in [0, 0.6], the linear part smaller, so that
    // 1 - B ranges over (0, 1] and the clamp sometimes acts.
    const int gvCells = shared::cellCount(res + 1);
    std::vector<float> blocking(std::size_t(4) * gvCells);
    for (int i = 0; i < gvCells; ++i) {
      blocking[i] = 0.3f * (uniform(random) + 1.0f);
      for (int k = 1; k < 4; ++k) blocking[std::size_t(k) * gvCells + i] = 0.4f * uniform(random);
    }
    shared::gvBlocking.assign(blocking.begin(), blocking.end());
    rig.loadGv(blocking, 1);
  }
  rig.propagate();
  const Grid gpuCurrent = rig.current(), gpuAccumulated = rig.accumulated();
  EXPECT_EQ(rig.normals(), normals) << "the injected normal grid is left as it was";

  Grid expectedAccumulated = accumulated;
  std::vector<float> n1 = dilate(normals, res);
  const Grid g1 = step(current, n1, res, expectedAccumulated);
  const std::vector<float> n2 = dilate(n1, res);
  const Grid expectedCurrent = step(g1, n2, res, expectedAccumulated, withGv);
  int normalLess = 0;
  forEachCell(res, [&](const glm::ivec3& c) { normalLess += !shared::directedHasNormal(normalOf(n1, res, c)); });
  std::cout << "[ directed ] " << withNormal << " of " << cells(res) << " cells with normals; "
            << normalLess << " still without after one dilation\n";

  expectClose(gpuCurrent, expectedCurrent, 1e-4, "current");
  expectClose(gpuAccumulated, expectedAccumulated, 1e-4, "accumulated");
}

TEST(DirectedPropagation, TwoGpuIterationsMatchTheSharedCppDilationAndGather) {
  twoIterationsMatchTheCpp(false);
}
TEST(DirectedPropagation, TwoGpuIterationsThroughAGeometryVolumeMatchTheSharedCpp) {
  twoIterationsMatchTheCpp(true);
}

// ---- b. normalisation and energy per iteration --------------------------------------------------

// r(+z) face by face (directed_faces.glsl): Omega_f / pi * max(0, 1/4 + w_f.z / 2) is face f's
// flux from a unit lobe about z, max(0, 1/4 + n_f.z / 2) what the unnormalised reprojection keeps.
TEST(DirectedPropagation, GainIsTheInverseOfWhatAnAxisLobeKeepsFaceByFace) {
  const double far = angles().farFace / M_PI, side = angles().sideFace / M_PI;
  auto lobe = [](double wz) { return std::max(0.0, 0.25 + 0.5 * wz); };
  const double up = far * lobe(1) * lobe(1) + 4 * side * lobe(2 / std::sqrt(5.0)) * lobe(0);
  const double lateral = far * lobe(0) * lobe(0) + 2 * side * lobe(0) * lobe(0) +
                         side * lobe(1 / std::sqrt(5.0)) * lobe(1) +
                         side * lobe(-1 / std::sqrt(5.0)) * lobe(-1);
  const double down = far * lobe(-1) * lobe(-1) + 4 * side * lobe(-2 / std::sqrt(5.0)) * lobe(0);
  const double r = up + 4 * lateral + down;
  std::cout << "[ directed ] an axis lobe keeps r = " << r << " per unnormalised step\n";
  for (const glm::dvec3 n : {glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0)})
    EXPECT_NEAR(1.0 / shared::directedGain(n, angles().farFace, angles().sideFace), r, 1e-12);
  // Off the axes the gain differs (the faces are not rotation invariant) but stays finite.
  const double g = shared::directedGain(glm::normalize(glm::dvec3(1, 2, 3)), angles().farFace,
                                        angles().sideFace);
  EXPECT_GT(g, 1.0);
  EXPECT_GT(std::abs(g - 1.0 / r), 1e-3);
}

void fluxIsKeptAlongTheNormal(const glm::dvec3& n) {
  const glm::ivec3 res{15, 15, 15}, centre{7, 7, 7};
  const int iterations = 6, radius = 3;  // light reaches the grid's edge at step 8
  auto chebyshev = [&](const glm::ivec3& c) {
    const glm::ivec3 d = glm::abs(c - centre);
    return std::max({d.x, d.y, d.z});
  };
  auto inside = [&](const glm::ivec3& c) { return chebyshev(c) <= radius; };
  const double phi = injectedFlux();
  const double r = 1.0 / shared::directedGain(n, angles().farFace, angles().sideFace);

  PropagationRig rig("directed", res, iterationsTable(1));
  Grid before = pointSource(res, centre, false, n);
  rig.load(before);
  std::vector<float> normals = vplNormals(res, centre, n);
  rig.loadNormals(normals);
  for (int k = 1; k <= iterations; ++k) {
    normals = dilate(normals, res);  // the C++ model's normals for step k
    rig.propagate();
    rig.loadNormals(normals);  // the rig dilates from the normal grid at every call
    const Grid after = rig.current();
    // The flux crossing the shell of radius R in the C++ model of this step.
    double outward = 0.0, inwardFlux = 0.0;
    forEachCell(res, [&](const glm::ivec3& c) {
      for (const glm::ivec3& d : kAxes) {
        const glm::ivec3 target = c + d;
        if (!shared::cellInside(target, res) || inside(c) == inside(target)) continue;
        for (int channel = 0; channel < 3; ++channel) {
          const double f = shared::shIntegral(received(before, normals, res, target, d, channel));
          (inside(c) ? outward : inwardFlux) += f;
        }
      }
    });
    const double total = flux(after, res), within = flux(after, res, inside);
    std::cout << "[ directed ] n = (" << n.x << "," << n.y << "," << n.z << ") it " << k
              << ": grid flux " << total / phi << " of injected (unnormalised: " << std::pow(r, k)
              << "), out of shell R=" << radius << ": " << outward << ", in: " << inwardFlux << "\n";
    EXPECT_NEAR(total, phi, 1e-5 * phi) << "iteration " << k;
    EXPECT_NEAR(within, flux(before, res, inside) - outward + inwardFlux, 1e-5 * phi)
        << "iteration " << k;
    if (k <= radius) {
      EXPECT_EQ(outward, 0.0) << "iteration " << k;
    } else {
      EXPECT_GT(outward, 1e-3 * phi) << "iteration " << k;
    }
    before = after;
  }
}

TEST(DirectedPropagation, AVplLobeKeepsItsFluxAmongItsDilatedNormalsAlongAnAxis) {
  fluxIsKeptAlongTheNormal({0, 0, 1});
}
TEST(DirectedPropagation, AVplLobeKeepsItsFluxAmongItsDilatedNormalsOffTheAxes) {
  fluxIsKeptAlongTheNormal(glm::normalize(glm::dvec3(1, 2, 3)));
}

// ---- c. what it fixes: back-propagation below the VPL's surface ---------------------------------

TEST(DirectedPropagation, AFloorVplLightsNothingBelowTheFloorWhereStandardDoes) {
  const glm::ivec3 res{15, 15, 15}, floorCell{7, 7, 7};
  const glm::dvec3 up{0, 1, 0};
  const int iterations = 7;
  auto below = [&](const glm::ivec3& c) { return c.y < floorCell.y; };
  PropagationRig standard("standard", res, iterationsTable(iterations));
  standard.load(pointSource(res, floorCell, false, up));
  standard.propagate();
  PropagationRig directed("directed", res, iterationsTable(iterations));
  directed.load(pointSource(res, floorCell, false, up));
  directed.loadNormals(vplNormals(res, floorCell, up));
  directed.propagate();
  const double phi = injectedFlux();
  const double standardBelow = flux(standard.accumulated(), res, below);
  const double directedBelow = flux(directed.accumulated(), res, below);
  const double directedAbove = flux(directed.accumulated(), res, [&](const glm::ivec3& c) { return c.y > 7; });
  std::cout << "[ directed ] accumulated below the floor after " << iterations
            << " iterations: standard " << standardBelow << " W, directed " << directedBelow
            << " W (above: " << directedAbove << " W)\n";
  EXPECT_GT(standardBelow, 0.05 * phi) << "standard propagation leaks behind the floor";
  // Every cell holds a lobe about +y, which is negative in every direction with w.y <= -2/sqrt(5)
  // that a step sends light downwards: nothing crosses the floor's plane.
  EXPECT_LT(directedBelow, 1e-6 * phi);
  EXPECT_GT(directedAbove, phi);
}

// Without dilation only the cells that received VPLs reproject; light that left them spreads
// as in standard propagation, and some of it gets below the floor again: the dilation is what
// carries the VPL's direction along with its light.
TEST(DirectedPropagation, WithoutDilationOnlyCellsWithNormalsReproject) {
  const glm::ivec3 res{9, 9, 9}, floorCell{4, 4, 4};
  const glm::dvec3 up{0, 1, 0};
  const int iterations = 4;
  toml::table table = iterationsTable(iterations);
  table.insert("dilation", false);
  PropagationRig rig("directed", res, table);
  rig.load(pointSource(res, floorCell, false, up));
  const std::vector<float> normals = vplNormals(res, floorCell, up);
  rig.loadNormals(normals);
  rig.propagate();
  Grid g = pointSource(res, floorCell, false, up), expected = g;
  for (int k = 0; k < iterations; ++k) g = step(g, normals, res, expected);
  const Grid gpu = rig.accumulated();
  const double tolerance = 1e-5 * maxAbs(expected);
  for (std::size_t i = 0; i < gpu.size(); ++i) ASSERT_NEAR(gpu[i], expected[i], tolerance) << i;
  const double phi = injectedFlux();
  EXPECT_GT(flux(gpu, res, [](const glm::ivec3& c) { return c.y < 4; }), 1e-3 * phi);
}

}  // namespace
}  // namespace lpvlab
