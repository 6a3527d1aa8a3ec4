// Tetrahedral propagation ("tetrahedral": shaders/propagation/tetrahedral_*.comp, and its CPU
// kernels, tetrahedral_cpu.h) through the whole strategy on hand-made cubic grids, at SH orders
// 1-3, every test on both backends:
//   - the kernels (split, gather steps, merge) against a double-precision C++ reference of any
//   order
//     built from the same shared GLSL (tetrahedral_lattice.glsl) and the same face integrals
//     (framework/math/tetrahedral_face_integrals.h) on random grids, without and with a random
//     geometry volume (unoccluded steps, then occluded ones), for both `face_flux` rules;
//   - resampling cubic -> lattice -> cubic conserves flux (zero steps);
//   - flux per step against the normalisation: the 12 far faces of a cell's four neighbours
//     tile the sphere, so a step from an isotropic source sends exactly its flux, and with the
//     face integrals a step from any source does up to the clamp; the clamp can only add, by at
//     most the factor computed below (> 1 for "centre", 1 for "integral"); until light reaches the
//     grid's boundary (the closed shell here) nothing is lost, and `accumulated` is the injected
//     light plus every step's, weighted by the step length (sqrt(2)/4 cube edges);
//   - a single VPL in the middle keeps the lattice's symmetries (it keeps all 48 of the cube's
//     about a cube centre: tests/math/tetrahedral_lattice_test.cpp), at orders 1 and 2;
//   - the GV: an opaque wall stops all light (0 W beyond it), a transparent GV changes nothing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "framework/math/tetrahedral_face_integrals.h"
#include "framework/math/tetrahedral_solid_angles.h"
#include "variants/resources/geometry_volume.h"
#include "order_grid_support.h"
#include "propagation_rig.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using namespace test;
using Cells = std::vector<double>;  // the lattice, grid.glsl's layout over tetSlotCount slots

// The strategy's `face_flux` rules: the exact face integrals, or solid angle x centroid intensity.
enum class FaceFlux { integral, centre };
const char* nameOf(FaceFlux rule) { return rule == FaceFlux::integral ? "integral" : "centre"; }

// The tetrahedral strategy and its light grid of cubes at `order`, with a GV if asked.
PropagationRig tetrahedralRig(const glm::ivec3& resolution, int iterations, int order = 1,
                              bool withGv = false, FaceFlux rule = FaceFlux::integral,
                              ComputeBackend backend = ComputeBackend::Gl) {
  toml::table table = iterationsTable(iterations);
  table.insert("face_flux", nameOf(rule));
  return PropagationRig("tetrahedral", resolution, table, order, withGv, backend);
}
const char* nameOf(ComputeBackend backend) { return backend == ComputeBackend::Cpu ? "cpu" : "gl"; }
void run(PropagationRig& rig, const Grid& current, const Grid& accumulated) {
  rig.load(current, accumulated);
  rig.propagate();
}
void run(PropagationRig& rig, const Grid& injected) { run(rig, injected, injected); }

// Every tetrahedral cell of the lattice inside the grid.
void forEachTet(const glm::ivec3& res, const std::function<void(const glm::ivec4&)>& f) {
  forEachCell(res, [&](const glm::ivec3& c) {
    for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
      const glm::ivec4 tet{c.x, c.y, c.z, code};
      if (shared::tetInside(tet, res)) f(tet);
    }
  });
}

// ---- the double-precision reference of split, gather and merge, at any order ------------------

struct Lattice {
  OrderGrid cubes;
  int slots() const { return shared::tetSlotCount(cubes.res); }
  std::size_t at(const glm::ivec4& tet, int channel, int k) const {
    return std::size_t(shared::coefficientIndex(channel, k, cubes.coefficients,
                                                shared::tetSlot(tet, cubes.res), slots()));
  }
  Cells zero() const { return Cells(std::size_t(3) * cubes.coefficients * slots(), 0.0); }
};

Cells split(const Grid& g, const Lattice& l) {
  Cells cells = l.zero();
  forEachTet(l.cubes.res, [&](const glm::ivec4& tet) {
    const glm::ivec3 lower{tet.x, tet.y, tet.z};
    const glm::ivec3 upper = lower + shared::tetUnitOffset(shared::tetAxis(tet.w));
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < l.cubes.coefficients; ++k)
        cells[l.at(tet, channel, k)] = shared::tetSplitWeight(lower, l.cubes.res) * g[l.cubes.at(lower, channel, k)] +
                                       shared::tetSplitWeight(upper, l.cubes.res) * g[l.cubes.at(upper, channel, k)];
  });
  return cells;
}

const TetrahedralFaceSolidAngles kAngles = tetrahedralFaceSolidAngles();

// What `tet` receives through its faces other than `sharedFace` from coefficients `c` (one
// channel) of its neighbour across it; `occluded`: through the GV in shared::gvBlocking.
std::vector<double> receive(const std::vector<double>& c, const glm::ivec4& tet, int sharedFace,
                            bool occluded, const glm::ivec3& res, FaceFlux rule) {
  std::vector<double> out(c.size(), 0.0);
  for (int k = 0; k < shared::TET_FACES; ++k) {
    if (k == sharedFace) continue;
    const glm::dvec3 w = shared::tetFarFaceDirection(tet.w, sharedFace, k);
    const glm::dvec3 normal = shared::tetFaceNormal(tet.w, k);
    const double omega = shared::tetFarFaceSolidAngle(sharedFace, k, kAngles.smallFace, kAngles.largeFace);
    const double transmittance =
        occluded ? shared::gvTransmittance(
                       shared::gvBlockingAt(shared::tetFarFaceCrossing(tet, sharedFace, k), res + 1), w)
                 : 1.0;
    double integral = 0.0;  // of the intensity over the face, exact or by its centroid
    for (std::size_t i = 0; i < c.size(); ++i)
      integral += c[i] * (rule == FaceFlux::integral
                              ? tetrahedralFaceIntegrals()[std::size_t(shared::tetFaceIntegralIndex(tet.w, sharedFace, k, int(i)))]
                              : omega * shared::shBasisAt(int(i), w));
    const double phi = shared::standardFaceFlux(integral, 1.0, transmittance);
    for (std::size_t i = 0; i < c.size(); ++i) out[i] += phi / M_PI * shared::shCosineLobeAt(int(i), normal);
  }
  return out;
}

Cells step(const Cells& source, const Lattice& l, bool occluded, FaceFlux rule) {
  Cells target = l.zero();
  const int n = l.cubes.coefficients;
  forEachTet(l.cubes.res, [&](const glm::ivec4& tet) {
    for (int face = 0; face < shared::TET_FACES; ++face) {
      const glm::ivec4 neighbour = shared::tetNeighbour(tet, face);
      if (!shared::tetInside(neighbour, l.cubes.res)) continue;
      for (int channel = 0; channel < 3; ++channel) {
        std::vector<double> c(n);
        for (int k = 0; k < n; ++k) c[k] = source[l.at(neighbour, channel, k)];
        const std::vector<double> got = receive(c, tet, face, occluded, l.cubes.res, rule);
        for (int k = 0; k < n; ++k) target[l.at(tet, channel, k)] += got[k];
      }
    }
  });
  return target;
}

Grid merge(const Cells& cells, const Lattice& l) {
  std::vector<double> sum(l.cubes.floats(), 0.0);
  forEachTet(l.cubes.res, [&](const glm::ivec4& tet) {
    const glm::ivec3 lower{tet.x, tet.y, tet.z};
    const glm::ivec3 upper = lower + shared::tetUnitOffset(shared::tetAxis(tet.w));
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < l.cubes.coefficients; ++k) {
        const double v = shared::TET_MERGE_WEIGHT * cells[l.at(tet, channel, k)];
        sum[l.cubes.at(lower, channel, k)] += v;
        sum[l.cubes.at(upper, channel, k)] += v;
      }
  });
  return Grid(sum.begin(), sum.end());
}

// ---- the clamp's gain -----------------------------------------------------------------------------

// The largest factor by which one step can multiply a cell's flux, over cells holding one
// clamped-cosine lobe Phi / pi * cosLobe(n) at `order` (n sampled densely, every cell
// orientation); a non-negative sum of lobes gains at most as much. Without the clamp it is
// exactly 1.
double maxStepGain(int order, FaceFlux rule) {
  double gain = 1.0;
  const int n = 2000, coefficients = shared::shCoefficientCount(order);
  for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
    const glm::ivec4 source{0, 0, 0, code};
    for (int i = 0; i < n; ++i) {
      const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
      const double phi = M_PI * (3.0 - std::sqrt(5.0)) * i;
      std::vector<double> lobe(coefficients);
      for (int k = 0; k < coefficients; ++k)
        lobe[k] = shared::shCosineLobeAt(k, {r * std::cos(phi), r * std::sin(phi), z}) / M_PI;
      double out = 0.0;
      for (int face = 0; face < shared::TET_FACES; ++face) {
        const glm::ivec4 target = shared::tetNeighbour(source, face);
        for (int back = 0; back < shared::TET_FACES; ++back)
          if (shared::tetNeighbour(target, back) == source)
            out += shared::shIntegralOfC0(receive(lobe, target, back, false, {1, 1, 1}, rule)[0]);
      }
      gain = std::max(gain, out);
    }
  }
  return gain;
}

class TetrahedralOrder : public ::testing::TestWithParam<std::tuple<int, ComputeBackend>> {
protected:
  int order() const { return std::get<0>(GetParam()); }
  ComputeBackend backend() const { return std::get<1>(GetParam()); }
};
// Order and face-flux rule.
class TetrahedralRule : public ::testing::TestWithParam<std::tuple<int, FaceFlux, ComputeBackend>> {
protected:
  int order() const { return std::get<0>(GetParam()); }
  FaceFlux rule() const { return std::get<1>(GetParam()); }
  ComputeBackend backend() const { return std::get<2>(GetParam()); }
};

// ---- a. the kernels against the C++ ------------------------------------------------------------

// With a GV: firstOccludedIteration 1, so the first tetFirstOccludedStep(1) = 3 steps are
// unoccluded and the rest read the random GV.
void kernelsMatchTheCpp(int order, bool withGv, FaceFlux rule, ComputeBackend backend) {
  const Lattice l{orderGrid({5, 4, 3}, order)};  // not multiples of the work group, nor a cube
  const int iterations = withGv ? 5 : 3;
  std::mt19937 random(2024 + order);
  const Grid current = randomFloats(l.cubes.floats(), random);
  const Grid accumulated = randomFloats(l.cubes.floats(), random);

  PropagationRig rig = tetrahedralRig(l.cubes.res, iterations, order, withGv, rule, backend);
  const int firstOccludedStep = shared::tetFirstOccludedStep(1);
  if (withGv) {
    ASSERT_EQ(firstOccludedStep, 3);
    const std::vector<float> blocking = test::randomBlocking(shared::cellCount(l.cubes.res + 1), random);
    shared::gvBlocking.assign(blocking.begin(), blocking.end());
    rig.loadGv(blocking, 1);
  }
  run(rig, current, accumulated);
  const Grid gpuCurrent = rig.current(), gpuAccumulated = rig.accumulated();

  Cells cells = split(current, l), sum = l.zero();
  for (int i = 0; i < iterations; ++i) {
    cells = step(cells, l, withGv && i >= firstOccludedStep, rule);
    for (std::size_t j = 0; j < sum.size(); ++j) sum[j] += cells[j];
  }
  const Grid expectedCurrent = merge(cells, l), merged = merge(sum, l);
  ASSERT_GT(maxAbs(expectedCurrent), 1e-3);
  Grid expectedAccumulated = accumulated;
  for (std::size_t i = 0; i < merged.size(); ++i)
    expectedAccumulated[i] += shared::TET_STEP_LENGTH * merged[i];
  expectClose(gpuCurrent, expectedCurrent, 1e-5, "current");
  expectClose(gpuAccumulated, expectedAccumulated, 1e-5, "accumulated");
}

TEST_P(TetrahedralRule, KernelsMatchTheSharedCppOnRandomGrids) {
  kernelsMatchTheCpp(order(), false, rule(), backend());
}
TEST_P(TetrahedralRule, KernelsThroughARandomGeometryVolumeMatchTheSharedCpp) {
  kernelsMatchTheCpp(order(), true, rule(), backend());
}

// ---- b. resampling and the normalisation ------------------------------------------------------

TEST_P(TetrahedralOrder, ResamplingConservesFlux) {
  const OrderGrid o = orderGrid({4, 3, 5}, order());
  std::mt19937 random(99);
  const Grid g = randomFloats(o.floats(), random);
  PropagationRig rig = tetrahedralRig(o.res, 0, order(), false, FaceFlux::integral, backend());
  run(rig, g);
  EXPECT_EQ(rig.accumulated(), g) << "no steps add nothing";
  const Grid resampled = rig.current();
  EXPECT_NEAR(flux(resampled, o), flux(g, o), 1e-5 * maxAbs(g) * double(o.floats()));
  EXPECT_GT(maxDifference(resampled, g), 0.1) << "the round trip smooths (half the cube, half its face neighbours)";
  // Every cube alone, corner ones included, keeps its flux.
  for (const glm::ivec3& cube : {glm::ivec3(0, 0, 0), glm::ivec3(3, 2, 4), glm::ivec3(1, 1, 2)}) {
    run(rig, orderSource(o, cube, false, glm::normalize(glm::dvec3(1, -2, 3))));
    EXPECT_NEAR(flux(rig.current(), o), injectedFlux(), 1e-6 * injectedFlux());
  }
}

void fluxPerStep(int order, bool isotropic, FaceFlux rule, ComputeBackend backend) {
  const OrderGrid o = orderGrid({11, 11, 11}, order);
  const glm::ivec3 centre{5, 5, 5};
  const int steps = 6;  // light moves 0.35 cubes per step (plus one cube of resampling each way):
                        // it stays well inside until then
  const double phi = injectedFlux(), gMax = maxStepGain(order, rule);
  const Grid injected = orderSource(o, centre, isotropic);
  std::cout << "[ tetrahedral ] order " << order << ", face flux " << nameOf(rule) << ", "
            << (isotropic ? "isotropic" : "+z cosine-lobe") << " source; largest clamp gain per step "
            << gMax << "\n";
  double before = phi, stepsFlux = 0.0;
  for (int k = 1; k <= steps; ++k) {
    PropagationRig rig = tetrahedralRig(o.res, k, order, false, rule, backend);
    run(rig, injected);
    const double now = flux(rig.current(), o), accumulated = flux(rig.accumulated(), o);
    std::cout << "[ tetrahedral ] order " << order << " step " << k << ": flux " << now / phi
              << " of injected, accumulated " << accumulated << " W\n";
    if (isotropic && k == 1) {
      EXPECT_NEAR(now, phi, 1e-5 * phi) << "the far faces tile the sphere";
    }
    EXPECT_GE(now, before * (1.0 - 1e-5)) << "step " << k << ": nothing leaves the grid yet";
    EXPECT_LE(now, before * gMax * (1.0 + 1e-5)) << "step " << k;
    stepsFlux += shared::TET_STEP_LENGTH * now;  // each step counts its length in cube edges
    EXPECT_NEAR(accumulated, phi + stepsFlux, 1e-5 * (phi + stepsFlux)) << "step " << k;
    before = now;
  }
  if (rule == FaceFlux::centre) {
    EXPECT_GT(gMax, 1.0) << "the clamp adds for some lobe";
  } else {
    EXPECT_LT(gMax, maxStepGain(order, FaceFlux::centre)) << "integrals clamp less than points";
  }
}

TEST_P(TetrahedralRule, FluxPerStepFromAnIsotropicSource) {
  fluxPerStep(order(), true, rule(), backend());
}
TEST_P(TetrahedralRule, FluxPerStepFromALobe) { fluxPerStep(order(), false, rule(), backend()); }

TEST(TetrahedralPropagation, LightLeavesASmallGrid) {
  const OrderGrid o = orderGrid({5, 5, 5}, 1);
  for (const ComputeBackend backend : {ComputeBackend::Gl, ComputeBackend::Cpu}) {
    PropagationRig rig = tetrahedralRig(o.res, 300, 1, false, FaceFlux::integral, backend);
    run(rig, orderSource(o, {2, 2, 2}, false));
    const double now = flux(rig.current(), o);
    ASSERT_TRUE(std::isfinite(now)) << nameOf(backend);
    EXPECT_GE(now, 0.0) << nameOf(backend);
    EXPECT_LT(now, 1e-4 * injectedFlux()) << nameOf(backend);
  }
}

// ---- c. symmetry -------------------------------------------------------------------------------

// The cube's symmetries about the centre cube's centre (grid_test_support.h), at orders 1 and 2.
const glm::ivec3 kRes11{11, 11, 11};
const glm::ivec3 kCentre11{5, 5, 5};

class TetrahedralSymmetry : public TetrahedralOrder {};

TEST_P(TetrahedralSymmetry, IsotropicVplKeepsTheCubesSymmetries) {
  const OrderGrid o = orderGrid(kRes11, order());
  PropagationRig rig = tetrahedralRig(kRes11, 7, order(), false, FaceFlux::integral, backend());
  run(rig, orderSource(o, kCentre11, true));
  for (const Grid& g : {rig.current(), rig.accumulated()}) {
    ASSERT_GT(maxAbs(g), 0.0);
    for (const Symmetry& s : {kMirrorX, kMirrorY, kMirrorZ, kSwapXY, kRotateZ, kRotateX, kRotateXYZ})
      EXPECT_LE(asymmetry(g, o, kCentre11, s), 1e-5 * maxAbs(g)) << s.name;
  }
}

TEST_P(TetrahedralSymmetry, LobeAlongZKeepsTheSymmetriesAboutZ) {
  const OrderGrid o = orderGrid(kRes11, order());
  PropagationRig rig = tetrahedralRig(kRes11, 7, order(), false, FaceFlux::integral, backend());
  run(rig, orderSource(o, kCentre11, false));
  for (const Grid& g : {rig.current(), rig.accumulated()}) {
    for (const Symmetry& s : {kMirrorX, kMirrorY, kSwapXY, kRotateZ})
      EXPECT_LE(asymmetry(g, o, kCentre11, s), 1e-5 * maxAbs(g)) << s.name;
    EXPECT_GT(asymmetry(g, o, kCentre11, kMirrorZ), 0.1 * maxAbs(g)) << "the light goes up";
  }
}

// ---- d. the geometry volume ---------------------------------------------------------------------

// A GV whose cells with x in [xLow, xHigh] block isotropically with B = blocking everywhere else
// zero (geometry_volume.h layout: c0 only).
std::vector<float> gvWall(const glm::ivec3& res, int xLow, int xHigh, double blocking) {
  const glm::ivec3 gvRes = res + 1;
  std::vector<float> gv(std::size_t(4) * shared::cellCount(gvRes), 0.0f);
  forEachCell(gvRes, [&](const glm::ivec3& c) {
    if (c.x >= xLow && c.x <= xHigh) gv[shared::cellIndex(c, gvRes)] = float(blocking / shared::SH_Y0);
  });
  return gv;
}

// GV cell centres sit on light-grid cube corners: cells x = 4..6 blocking B = 1000 make every
// crossing point with 3.001 < x < 6.999 opaque; a lattice step moves light 0.35 cube edges and
// crosses a face between its two centroids, so no light gets from x < 4 to x > 7 (cubes x >= 7
// are fed only by lattice cells whose centroids have x > 6.75).
TEST_P(TetrahedralOrder, AnOpaqueGvWallStopsTheLight) {
  const OrderGrid o = orderGrid({12, 5, 5}, order());
  const glm::ivec3 source{1, 2, 2};
  const int steps = 40;  // enough to cross the grid about once without the wall
  auto beyond = [](const glm::ivec3& c) { return c.x >= 7; };
  PropagationRig open = tetrahedralRig(o.res, steps, order(), false, FaceFlux::integral, backend());
  run(open, orderSource(o, source, false, {1, 0, 0}));
  const double openBeyond = flux(open.accumulated(), o, beyond);
  PropagationRig walled =
      tetrahedralRig(o.res, steps, order(), true, FaceFlux::integral, backend());
  walled.loadGv(gvWall(o.res, 4, 6, 1000.0), 0);
  run(walled, orderSource(o, source, false, {1, 0, 0}));
  const Grid g = walled.accumulated();
  double walledBeyond = 0.0;
  forEachCell(o.res, [&](const glm::ivec3& c) {
    if (!beyond(c)) return;
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < o.coefficients; ++k) walledBeyond += std::abs(g[o.at(c, channel, k)]);
  });
  std::cout << "[ tetrahedral ] " << nameOf(backend()) << ", order " << order()
            << ": accumulated beyond the wall: open " << openBeyond << " W, walled " << walledBeyond
            << " (sum of |coefficients|)\n";
  EXPECT_GT(openBeyond, 1e-4 * injectedFlux()) << "without the wall light gets there";
  EXPECT_EQ(walledBeyond, 0.0);
  EXPECT_GT(flux(g, o, [](const glm::ivec3& c) { return c.x < 4; }), injectedFlux())
      << "the light before the wall is still there";
}

TEST_P(TetrahedralOrder, ATransparentGvChangesNothing) {
  const OrderGrid o = orderGrid({6, 5, 4}, order());
  std::mt19937 random(7);
  const Grid current = randomFloats(o.floats(), random), accumulated = randomFloats(o.floats(), random);
  PropagationRig plain = tetrahedralRig(o.res, 6, order(), false, FaceFlux::integral, backend());
  run(plain, current, accumulated);
  PropagationRig withGv = tetrahedralRig(o.res, 6, order(), true, FaceFlux::integral, backend());
  withGv.loadGv(gvWall(o.res, 0, o.res.x, 0.0), 0);
  run(withGv, current, accumulated);
  expectClose(withGv.current(), plain.current(), 1e-6, "current");
  expectClose(withGv.accumulated(), plain.accumulated(), 1e-6, "accumulated");
}

const auto kBackends = ::testing::Values(ComputeBackend::Gl, ComputeBackend::Cpu);
std::string orderAndBackend(const ::testing::TestParamInfo<std::tuple<int, ComputeBackend>>& info) {
  return "order" + std::to_string(std::get<0>(info.param)) + "_" + nameOf(std::get<1>(info.param));
}
INSTANTIATE_TEST_SUITE_P(OrdersAndBackends, TetrahedralOrder,
                         ::testing::Combine(::testing::Values(1, 2, 3), kBackends),
                         orderAndBackend);
INSTANTIATE_TEST_SUITE_P(OrdersRulesAndBackends, TetrahedralRule,
                         ::testing::Combine(::testing::Values(1, 2, 3),
                                            ::testing::Values(FaceFlux::integral, FaceFlux::centre),
                                            kBackends),
                         [](const auto& info) {
                           return "order" + std::to_string(std::get<0>(info.param)) + "_" +
                                  nameOf(std::get<1>(info.param)) + "_" +
                                  nameOf(std::get<2>(info.param));
                         });
INSTANTIATE_TEST_SUITE_P(OrdersAndBackends, TetrahedralSymmetry,
                         ::testing::Combine(::testing::Values(1, 2), kBackends), orderAndBackend);

}  // namespace
}  // namespace lpvlab
