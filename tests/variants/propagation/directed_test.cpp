// Directed propagation ("directed", shaders/propagation/directed_*.comp, and its CPU kernel,
// directed_cpu.h) on hand-made grids, the kernels' tests on both backends:
//   - the kernels' dilation, release and gather are the double-precision C++ of the same shared
//     GLSL (directed_faces.glsl), over two iterations of random light and a sparse random normal
//     grid, without and with a random geometry volume (occluding from the second iteration on),
//     with release (the default: attached and free light) and read literally (release = false);
//   - the normalisation: 1 / G(n) is what one unnormalised step keeps of a lobe about n, which
//     for an axis normal is written out here face by face; with G, a VPL's lobe propagating among
//     the normals dilated from its own keeps its flux at every iteration (the flux within a
//     closed shell changes only by what crosses it), where the unnormalised step would keep r^k;
//   - the point of the method: a VPL on a floor facing +y lights nothing below the floor (order
//     1; at orders 2-3 the SH lobe's ringing lets 2.5% of standard propagation's light through),
//     where standard propagation does;
//   all at SH orders 1-3.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <tuple>

#include "directed_model.h"
#include "framework/math/solid_angle.h"
#include "variants/resources/geometry_volume.h"
#include "order_grid_support.h"
#include "propagation_rig.h"

namespace lpvlab {
namespace {

using namespace test;

const CubeFaceSolidAngles& angles() {
  static const CubeFaceSolidAngles a = cubeFaceSolidAngles();
  return a;
}

// ---- the double-precision model: the shared GLSL, dilated (directed_model.h) and gathered as ----
// ---- the kernels do -----------------------------------------------------------------------------

// What `cell`'s neighbour at cell - d sends it along d, per channel, at the grid's order;
// `occluded`: through the GV in shared::gvBlocking.
std::vector<double> received(const Grid& g, const OrderGrid& o, const std::vector<float>& normals,
                             const glm::ivec3& cell, const glm::ivec3& d, int channel,
                             bool occluded = false) {
  const glm::ivec3& res = o.res;
  const glm::dvec4 stored = normalOf(normals, res, cell);
  const glm::dvec3 n = shared::directedUnitNormal(stored);
  const double gain = shared::directedGainOf(stored, angles().farFace, angles().sideFace, o.coefficients);
  const glm::dvec3 axis(d), sourceCentre = glm::dvec3(cell - d) + 0.5;
  std::vector<double> sum(o.coefficients, 0.0);
  for (int f = 0; f < shared::STANDARD_FACES; ++f) {
    const glm::dvec3 w = shared::standardFaceDirection(axis, f), faceNormal = shared::standardFaceNormal(axis, f);
    const double transmittance =
        occluded ? shared::gvTransmittance(
                       shared::gvBlockingAt(shared::standardFaceCrossing(sourceCentre, axis, f), res + 1), w)
                 : 1.0;
    const double intensity = o.evaluate(g, cell - d, channel, w);
    const double phi = shared::standardFaceFlux(
        intensity, shared::standardFaceSolidAngle(f, angles().farFace, angles().sideFace), transmittance);
    for (int k = 0; k < o.coefficients; ++k)
      sum[k] += gain == 0.0
                    ? phi / M_PI * shared::shCosineLobeAt(k, faceNormal)
                    : phi * shared::directedReprojection(faceNormal, n, gain, o.coefficients) *
                          shared::shCosineLobeAt(k, n);
  }
  return sum;
}

// One gather step: the new light, added to `accumulated`.
Grid step(const Grid& g, const OrderGrid& o, const std::vector<float>& normals, Grid& accumulated,
          bool occluded = false) {
  Grid out(g.size(), 0.0f);
  forEachCell(o.res, [&](const glm::ivec3& cell) {
    for (int channel = 0; channel < 3; ++channel) {
      std::vector<double> sum(o.coefficients, 0.0);
      for (const glm::ivec3& d : kAxes)
        if (shared::cellInside(cell - d, o.res)) {
          const std::vector<double> got = received(g, o, normals, cell, d, channel, occluded);
          for (int k = 0; k < o.coefficients; ++k) sum[k] += got[k];
        }
      for (int k = 0; k < o.coefficients; ++k) {
        out[o.at(cell, channel, k)] = float(sum[k]);
        accumulated[o.at(cell, channel, k)] += float(sum[k]);
      }
    }
  });
  return out;
}

// Release (directed_faces.glsl): before a step, every cell without a normal, or with a neighbour
// whose normal is of another region (`cosRegionAngle`), moves its attached light into the free
// grid. Returns how many cells keep theirs.
int release(Grid& attached, Grid& free, const OrderGrid& o, const std::vector<float>& normals,
            double cosRegionAngle) {
  int kept = 0;
  forEachCell(o.res, [&](const glm::ivec3& cell) {
    const glm::dvec4 own = normalOf(normals, o.res, cell);
    bool releases = !shared::directedHasNormal(own);
    for (const glm::ivec3& d : kAxes)
      if (shared::cellInside(cell + d, o.res) &&
          shared::directedNeighbourReleases(own, normalOf(normals, o.res, cell + d), cosRegionAngle))
        releases = true;
    if (!releases) {
      ++kept;
      return;
    }
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < o.coefficients; ++k) {
        free[o.at(cell, channel, k)] += attached[o.at(cell, channel, k)];
        attached[o.at(cell, channel, k)] = 0.0f;
      }
  });
  return kept;
}

// The default region angle's cosine (directed.cpp's region_angle_deg = 10).
double defaultCosRegionAngle() { return std::cos(10.0 * M_PI / 180.0); }

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
// `released`: the default, light in two grids released at the regions' boundaries; else alg. 6.3
// read literally (release = false), one grid.
void twoIterationsMatchTheCpp(int order, ComputeBackend backend, bool withGv, bool released = true) {
  const glm::ivec3 res{6, 5, 4};  // not multiples of the 4^3 work group, nor a cube
  const OrderGrid o = orderGrid(res, order);
  std::mt19937 random(4242 + order);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  const Grid current = randomFloats(o.floats(), random), accumulated = randomFloats(o.floats(), random);
  // A sparse grid, so that dilation has work at both steps; released, of regions (random normals
  // would release every cell).
  std::vector<float> normals(std::size_t(4) * cells(res), 0.0f);
  if (released) {
    normals = regionNormals(res, random, 0.4f);
  } else {
    for (std::size_t i = 0; i < normals.size(); i += 4)
      if (uniform(random) > 0.6f) {
        for (int k = 0; k < 3; ++k) normals[i + k] = uniform(random);
        normals[i + 3] = 1.0f;
      }
  }
  int withNormal = 0;
  for (std::size_t i = 0; i < normals.size(); i += 4) withNormal += normals[i + 3] != 0.0f;
  ASSERT_GT(withNormal, 3);

  toml::table table = iterationsTable(2);
  if (!released) table.insert("release", false);
  PropagationRig rig("directed", res, table, order, withGv, backend);
  rig.load(current, accumulated);
  rig.loadNormals(normals);
  if (withGv) {
    const std::vector<float> blocking = test::randomBlocking(shared::cellCount(res + 1), random);
    shared::gvBlocking.assign(blocking.begin(), blocking.end());
    rig.loadGv(blocking, 1);
  }
  rig.propagate();
  const Grid gpuCurrent = rig.current(), gpuAccumulated = rig.accumulated();
  EXPECT_EQ(rig.normals(), normals) << "the injected normal grid is left as it was";

  Grid expectedAccumulated = accumulated, expectedCurrent;
  std::vector<float> n1 = dilate(normals, res);
  const std::vector<float> n2 = dilate(n1, res);
  if (released) {
    // The free light propagates as standard: as through cells without normals.
    const std::vector<float> none(normals.size(), 0.0f);
    Grid attached = current, free(current.size(), 0.0f);
    const int kept = release(attached, free, o, n1, defaultCosRegionAngle());
    attached = step(attached, o, n1, expectedAccumulated);
    free = step(free, o, none, expectedAccumulated);
    EXPECT_GT(kept + release(attached, free, o, n2, defaultCosRegionAngle()), 10)
        << "cells keep attached light, so the reprojection is compared too";
    attached = step(attached, o, n2, expectedAccumulated, withGv);
    free = step(free, o, none, expectedAccumulated, withGv);
    expectedCurrent = attached;
    for (std::size_t i = 0; i < free.size(); ++i) expectedCurrent[i] += free[i];
  } else {
    const Grid g1 = step(current, o, n1, expectedAccumulated);
    expectedCurrent = step(g1, o, n2, expectedAccumulated, withGv);
  }
  int normalLess = 0;
  forEachCell(res, [&](const glm::ivec3& c) { normalLess += !shared::directedHasNormal(normalOf(n1, res, c)); });
  std::cout << "[ directed ] " << withNormal << " of " << cells(res) << " cells with normals; "
            << normalLess << " still without after one dilation\n";

  expectClose(gpuCurrent, expectedCurrent, 1e-4, "current");
  expectClose(gpuAccumulated, expectedAccumulated, 1e-4, "accumulated");
}

class DirectedOrder : public ::testing::TestWithParam<int> {};
// The kernels' tests: per SH order and backend.
class DirectedKernel : public ::testing::TestWithParam<std::tuple<int, ComputeBackend>> {
protected:
  int order() const { return std::get<0>(GetParam()); }
  ComputeBackend backend() const { return std::get<1>(GetParam()); }
};

TEST_P(DirectedKernel, TwoIterationsMatchTheSharedCppDilationAndGather) {
  twoIterationsMatchTheCpp(order(), backend(), false);
}
TEST_P(DirectedKernel, TwoIterationsThroughAGeometryVolumeMatchTheSharedCpp) {
  twoIterationsMatchTheCpp(order(), backend(), true);
}
TEST_P(DirectedKernel, TwoIterationsReadLiterallyMatchTheSharedCpp) {
  twoIterationsMatchTheCpp(order(), backend(), false, false);
  twoIterationsMatchTheCpp(order(), backend(), true, false);
}

// ---- b. normalisation and energy per iteration --------------------------------------------------

// r_L(+z) face by face (directed_faces.glsl): Omega_f / pi * max(0, l(w_f.z)) is face f's flux
// from a unit lobe about z, max(0, l(n_f.z)) what the unnormalised reprojection keeps, with the
// lobe profile l written out per order: l_1(t) = 1/4 + t/2, l_2 = l_3 = l_1 + 5/16 P_2(t).
TEST_P(DirectedOrder, GainIsTheInverseOfWhatAnAxisLobeKeepsFaceByFace) {
  const int order = GetParam(), coefficients = shared::shCoefficientCount(order);
  const double far = angles().farFace / M_PI, side = angles().sideFace / M_PI;
  auto lobe = [&](double t) {
    const double p2 = order >= 2 ? 5.0 / 16.0 * (3.0 * t * t - 1.0) / 2.0 : 0.0;
    return std::max(0.0, 0.25 + 0.5 * t + p2);
  };
  const double up = far * lobe(1) * lobe(1) + 4 * side * lobe(2 / std::sqrt(5.0)) * lobe(0);
  const double lateral = far * lobe(0) * lobe(0) + 2 * side * lobe(0) * lobe(0) +
                         side * lobe(1 / std::sqrt(5.0)) * lobe(1) +
                         side * lobe(-1 / std::sqrt(5.0)) * lobe(-1);
  const double down = far * lobe(-1) * lobe(-1) + 4 * side * lobe(-2 / std::sqrt(5.0)) * lobe(0);
  const double r = up + 4 * lateral + down;
  std::cout << "[ directed ] order " << order << ": an axis lobe keeps r = " << r
            << " per unnormalised step\n";
  for (const glm::dvec3 n : {glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0)})
    EXPECT_NEAR(1.0 / shared::directedGain(n, angles().farFace, angles().sideFace, coefficients), r, 1e-12);
  // Off the axes the gain differs (the faces are not rotation invariant) but stays finite.
  const double g = shared::directedGain(glm::normalize(glm::dvec3(1, 2, 3)), angles().farFace,
                                        angles().sideFace, coefficients);
  EXPECT_GT(g, 1.0);
  EXPECT_GT(std::abs(g - 1.0 / r), 1e-3);
}

// The lobe profile l_L(a . b) by Legendre polynomials is the projected lobe evaluated by the basis.
TEST_P(DirectedOrder, LobeValueIsTheProjectedCosineLobeEvaluated) {
  const int coefficients = shared::shCoefficientCount(GetParam());
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 100; ++i) {
    const glm::dvec3 a = glm::normalize(glm::dvec3(normal(random), normal(random), normal(random)));
    const glm::dvec3 b = glm::normalize(glm::dvec3(normal(random), normal(random), normal(random)));
    double sum = 0.0;
    for (int k = 0; k < coefficients; ++k) sum += shared::shCosineLobeAt(k, a) * shared::shBasisAt(k, b);
    EXPECT_NEAR(shared::directedLobeValue(a, b, coefficients), sum, 1e-12);
  }
}

// Order 3 reprojects as order 2 (z_3 = 0) but its gain comes from the same loop over 16
// coefficients: the band-3 terms must cancel.
TEST(DirectedPropagation, OrderThreeGainIsOrderTwos) {
  for (const glm::dvec3 n : {glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(1, 2, 3))})
    EXPECT_NEAR(shared::directedGain(n, angles().farFace, angles().sideFace, 16),
                shared::directedGain(n, angles().farFace, angles().sideFace, 9), 1e-12);
}

void fluxIsKeptAlongTheNormal(int order, ComputeBackend backend, const glm::dvec3& n) {
  const glm::ivec3 res{15, 15, 15}, centre{7, 7, 7};
  const OrderGrid o = orderGrid(res, order);
  const int iterations = 6, radius = 3;  // light reaches the grid's edge at step 8
  auto chebyshev = [&](const glm::ivec3& c) {
    const glm::ivec3 d = glm::abs(c - centre);
    return std::max({d.x, d.y, d.z});
  };
  auto inside = [&](const glm::ivec3& c) { return chebyshev(c) <= radius; };
  const double phi = injectedFlux();
  const double r = 1.0 / shared::directedGain(n, angles().farFace, angles().sideFace, o.coefficients);

  PropagationRig rig("directed", res, iterationsTable(1), order, false, backend);
  Grid before = orderSource(o, centre, false, n);
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
          const double f = shared::shIntegralOfC0(received(before, o, normals, target, d, channel)[0]);
          (inside(c) ? outward : inwardFlux) += f;
        }
      }
    });
    const double total = flux(after, o), within = flux(after, o, inside);
    std::cout << "[ directed ] order " << order << ", n = (" << n.x << "," << n.y << "," << n.z
              << ") it " << k << ": grid flux " << total / phi << " of injected (unnormalised: "
              << std::pow(r, k) << "), out of shell R=" << radius << ": " << outward << ", in: "
              << inwardFlux << "\n";
    EXPECT_NEAR(total, phi, 1e-5 * phi) << "iteration " << k;
    EXPECT_NEAR(within, flux(before, o, inside) - outward + inwardFlux, 1e-5 * phi)
        << "iteration " << k;
    if (k <= radius) {
      EXPECT_EQ(outward, 0.0) << "iteration " << k;
    } else {
      EXPECT_GT(outward, 1e-3 * phi) << "iteration " << k;
    }
    before = after;
  }
}

TEST_P(DirectedKernel, AVplLobeKeepsItsFluxAmongItsDilatedNormalsAlongAnAxis) {
  fluxIsKeptAlongTheNormal(order(), backend(), {0, 0, 1});
}
TEST_P(DirectedKernel, AVplLobeKeepsItsFluxAmongItsDilatedNormalsOffTheAxes) {
  fluxIsKeptAlongTheNormal(order(), backend(), glm::normalize(glm::dvec3(1, 2, 3)));
}

// ---- c. what it fixes: back-propagation below the VPL's surface ---------------------------------

TEST_P(DirectedKernel, AFloorVplLightsNothingBelowTheFloorWhereStandardDoes) {
  const int order = this->order();
  const glm::ivec3 res{15, 15, 15}, floorCell{7, 7, 7};
  const OrderGrid o = orderGrid(res, order);
  const glm::dvec3 up{0, 1, 0};
  const int iterations = 7;
  auto below = [&](const glm::ivec3& c) { return c.y < floorCell.y; };
  PropagationRig standard("standard", res, iterationsTable(iterations), order, false, backend());
  standard.load(orderSource(o, floorCell, false, up));
  standard.propagate();
  PropagationRig directed("directed", res, iterationsTable(iterations), order, false, backend());
  directed.load(orderSource(o, floorCell, false, up));
  directed.loadNormals(vplNormals(res, floorCell, up));
  directed.propagate();
  const double phi = injectedFlux();
  const double standardBelow = flux(standard.accumulated(), o, below);
  const double directedBelow = flux(directed.accumulated(), o, below);
  const double directedAbove = flux(directed.accumulated(), o, [&](const glm::ivec3& c) { return c.y > 7; });
  std::cout << "[ directed ] order " << order << ": accumulated below the floor after " << iterations
            << " iterations: standard " << standardBelow << " W, directed " << directedBelow
            << " W (above: " << directedAbove << " W)\n";
  EXPECT_GT(standardBelow, 0.05 * phi) << "standard propagation leaks behind the floor";
  EXPECT_GT(directedAbove, phi);
  if (order == 1) {
    // Every cell holds a lobe about +y, negative in every direction with w.y <= -2/sqrt(5) that a
    // step sends light downwards: nothing crosses the floor's plane.
    EXPECT_LT(directedBelow, 1e-6 * phi);
  } else {
    // The order-2 lobe rings: l_2(-1) = 1/16 and l_2(-2/sqrt 5) = 0.022 are positive, so faces
    // pointing down pass a little light (as a lobe about +y, one cell lower). Far less than
    // standard propagation, but not nothing (directed_faces.glsl).
    EXPECT_GT(directedBelow, 1e-4 * phi);
    EXPECT_LT(directedBelow, 0.05 * standardBelow);
  }
}

// Without dilation only the cells that received VPLs reproject; light that left them spreads
// as in standard propagation, and some of it gets below the floor again: the dilation is what
// carries the VPL's direction along with its light.
class DirectedBackend : public ::testing::TestWithParam<ComputeBackend> {};

TEST_P(DirectedBackend, WithoutDilationOnlyCellsWithNormalsReproject) {
  const glm::ivec3 res{9, 9, 9}, floorCell{4, 4, 4};
  const OrderGrid o = orderGrid(res, 1);
  const glm::dvec3 up{0, 1, 0};
  const int iterations = 4;
  toml::table table = iterationsTable(iterations);
  table.insert("dilation", false);
  PropagationRig rig("directed", res, table, 1, false, GetParam());
  rig.load(orderSource(o, floorCell, false, up));
  const std::vector<float> normals = vplNormals(res, floorCell, up);
  rig.loadNormals(normals);
  rig.propagate();
  // The VPL's cell keeps its light attached (its neighbours have no normal); what it sends into
  // them gets the standard transfer and is released the step after.
  Grid attached = orderSource(o, floorCell, false, up), expected = attached,
       free(attached.size(), 0.0f);
  const std::vector<float> none(normals.size(), 0.0f);
  for (int k = 0; k < iterations; ++k) {
    release(attached, free, o, normals, defaultCosRegionAngle());
    attached = step(attached, o, normals, expected);
    free = step(free, o, none, expected);
  }
  const Grid gpu = rig.accumulated();
  const double tolerance = 1e-5 * maxAbs(expected);
  for (std::size_t i = 0; i < gpu.size(); ++i) ASSERT_NEAR(gpu[i], expected[i], tolerance) << i;
  const double phi = injectedFlux();
  EXPECT_GT(flux(gpu, o, [](const glm::ivec3& c) { return c.y < 4; }), 1e-3 * phi);
}

INSTANTIATE_TEST_SUITE_P(Orders, DirectedOrder, ::testing::Values(1, 2, 3),
                         [](const auto& info) { return "order" + std::to_string(info.param); });
INSTANTIATE_TEST_SUITE_P(Backends, DirectedBackend,
                         ::testing::Values(ComputeBackend::Gl, ComputeBackend::Cpu),
                         [](const auto& info) {
                           return info.param == ComputeBackend::Cpu ? "cpu" : "gl";
                         });
INSTANTIATE_TEST_SUITE_P(OrdersAndBackends, DirectedKernel,
                         ::testing::Combine(::testing::Values(1, 2, 3),
                                            ::testing::Values(ComputeBackend::Gl,
                                                              ComputeBackend::Cpu)),
                         [](const auto& info) {
                           return "order" + std::to_string(std::get<0>(info.param)) +
                                  (std::get<1>(info.param) == ComputeBackend::Cpu ? "_cpu" : "_gl");
                         });

}  // namespace
}  // namespace lpvlab
