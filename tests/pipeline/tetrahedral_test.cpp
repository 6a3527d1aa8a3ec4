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
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/tetrahedral_solid_angles.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"
#include "pipeline_test_support.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

constexpr int kCoefficients = 4;
using Grid = std::vector<float>;     // grid.glsl layout, 3 channels, 4 coefficients
using Cells = std::vector<double>;   // the lattice, same layout over tetSlotCount slots

class TetrahedralRig {
public:
  TetrahedralRig(const glm::ivec3& resolution, int iterations) {
    test::glTestContext();
    table_.insert("iterations", iterations);
    Params params(table_, "tetrahedral test", "propagation");
    strategy_ = Registry<PropagationStrategy>::instance().create(params, "tetrahedral");
    params.finish();
    const GridGeometry geometry{glm::vec3(0.0f), 1.0f, resolution};
    Requirements requirements;
    strategy_->declare(requirements);
    strategy_->prepare(shaders_, geometry, requirements);
    grid_ = LightGrid(geometry, requirements.shOrder);
  }
  void run(const Grid& current, const Grid& accumulated) {
    grid_.current.upload(current.data(), current.size() * sizeof(float));
    grid_.accumulated.upload(accumulated.data(), accumulated.size() * sizeof(float));
    Frame frame{.gbuffer = gbuffer_, .lightMaps = lightMaps_, .lightGrid = grid_, .indirect = indirect_};
    strategy_->propagate(frame);
    checkGl("tetrahedral test");
  }
  void run(const Grid& injected) { run(injected, injected); }
  Grid current() const { return download(grid_.current); }
  Grid accumulated() const { return download(grid_.accumulated); }

private:
  Grid download(const gl::Buffer& buffer) const {
    Grid data(grid_.floatsPerGrid());
    buffer.download(data.data(), data.size() * sizeof(float));
    return data;
  }
  toml::table table_;
  ShaderCompiler shaders_;
  std::unique_ptr<PropagationStrategy> strategy_;
  LightGrid grid_;
  GBuffer gbuffer_;
  LightMaps lightMaps_;
  gl::Texture indirect_;
};

int cubes(const glm::ivec3& res) { return shared::cellCount(res); }

std::size_t at(const glm::ivec3& res, const glm::ivec3& cube, int channel, int k) {
  return std::size_t(shared::coefficientIndex(channel, k, kCoefficients,
                                              shared::cellIndex(cube, res), cubes(res)));
}

std::size_t slotAt(const glm::ivec3& res, const glm::ivec4& tet, int channel, int k) {
  return std::size_t(shared::coefficientIndex(channel, k, kCoefficients,
                                              shared::tetSlot(tet, res), shared::tetSlotCount(res)));
}

void forEachCube(const glm::ivec3& res, const std::function<void(const glm::ivec3&)>& f) {
  for (int z = 0; z < res.z; ++z)
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) f({x, y, z});
}

void forEachCell(const glm::ivec3& res, const std::function<void(const glm::ivec4&)>& f) {
  forEachCube(res, [&](const glm::ivec3& c) {
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

glm::dvec4 cubeOf(const Grid& g, const glm::ivec3& res, const glm::ivec3& cube, int channel) {
  glm::dvec4 c;
  for (int k = 0; k < kCoefficients; ++k) c[k] = g[at(res, cube, channel, k)];
  return c;
}

double flux(const Grid& g, const glm::ivec3& res) {
  double sum = 0.0;
  forEachCube(res, [&](const glm::ivec3& c) {
    for (int channel = 0; channel < 3; ++channel) sum += shared::shIntegral(cubeOf(g, res, c, channel));
  });
  return sum;
}

double maxAbs(const Grid& g) {
  double m = 0.0;
  for (float v : g) m = std::max(m, double(std::abs(v)));
  return m;
}

// ---- the double-precision reference of split, gather and merge --------------------------------

Cells split(const Grid& g, const glm::ivec3& res) {
  Cells cells(std::size_t(3) * kCoefficients * shared::tetSlotCount(res), 0.0);
  forEachCell(res, [&](const glm::ivec4& tet) {
    const glm::ivec3 lower{tet.x, tet.y, tet.z};
    const glm::ivec3 upper = lower + shared::tetUnitOffset(shared::tetAxis(tet.w));
    for (int channel = 0; channel < 3; ++channel) {
      const glm::dvec4 c = shared::tetSplitWeight(lower, res) * cubeOf(g, res, lower, channel) +
                           shared::tetSplitWeight(upper, res) * cubeOf(g, res, upper, channel);
      for (int k = 0; k < kCoefficients; ++k) cells[slotAt(res, tet, channel, k)] = c[k];
    }
  });
  return cells;
}

const TetrahedralFaceSolidAngles kAngles = tetrahedralFaceSolidAngles();

Cells step(const Cells& source, const glm::ivec3& res) {
  Cells target(source.size(), 0.0);
  forEachCell(res, [&](const glm::ivec4& tet) {
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
  std::vector<double> sum(std::size_t(3) * kCoefficients * cubes(res), 0.0);
  forEachCell(res, [&](const glm::ivec4& tet) {
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

// ---- sources -----------------------------------------------------------------------------------

const double kChannelFlux[3] = {1.0, 0.5, 0.25};
double injectedFlux() { return kChannelFlux[0] + kChannelFlux[1] + kChannelFlux[2]; }

Grid pointSource(const glm::ivec3& res, const glm::ivec3& cube, bool isotropic) {
  Grid g(std::size_t(3) * kCoefficients * cubes(res), 0.0f);
  for (int channel = 0; channel < 3; ++channel) {
    const double phi = kChannelFlux[channel];
    const glm::dvec4 c = isotropic ? glm::dvec4(phi / (2.0 * std::sqrt(M_PI)), 0, 0, 0)
                                   : phi / M_PI * shared::shCosineLobe({0, 0, 1});
    for (int k = 0; k < kCoefficients; ++k) g[at(res, cube, channel, k)] = float(c[k]);
  }
  return g;
}

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
  const std::size_t n = std::size_t(3) * kCoefficients * cubes(res);
  std::mt19937 random(2024);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  Grid current(n), accumulated(n);
  for (float& v : current) v = uniform(random);
  for (float& v : accumulated) v = uniform(random);

  TetrahedralRig rig(res, iterations);
  rig.run(current, accumulated);
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
  const std::size_t n = std::size_t(3) * kCoefficients * cubes(res);
  std::mt19937 random(99);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  Grid g(n);
  for (float& v : g) v = uniform(random);
  TetrahedralRig rig(res, 0);
  rig.run(g);
  EXPECT_EQ(rig.accumulated(), g) << "no steps add nothing";
  const Grid resampled = rig.current();
  EXPECT_NEAR(flux(resampled, res), flux(g, res), 1e-5 * maxAbs(g) * double(n));
  double differs = 0.0;  // the round trip smooths (half the cube, half its face neighbours)
  for (std::size_t i = 0; i < n; ++i) differs = std::max(differs, double(std::abs(resampled[i] - g[i])));
  EXPECT_GT(differs, 0.1);
  // Every cube alone, corner ones included, keeps its flux.
  for (const glm::ivec3& cube : {glm::ivec3(0, 0, 0), glm::ivec3(3, 2, 4), glm::ivec3(1, 1, 2)}) {
    const Grid one = pointSource(res, cube, true);
    rig.run(one);
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
    TetrahedralRig rig(res, k);
    rig.run(injected);
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
  TetrahedralRig rig(res, 300);
  rig.run(pointSource(res, {2, 2, 2}, false));
  const double now = flux(rig.current(), res);
  ASSERT_TRUE(std::isfinite(now));
  EXPECT_GE(now, 0.0);
  EXPECT_LT(now, 1e-4 * injectedFlux());
}

// ---- c. symmetry -------------------------------------------------------------------------------

// A symmetry of the cube about `centre`'s cube centre: the signed permutation P acting on cube
// offsets and on directions; an order-1 SH a + b.w maps to a + (P b).w, and with
// (c0, c1, c2, c3) = (a, -y, z, -x) (up to constants) b = (-c3, -c1, c2).
struct Symmetry {
  std::string name;
  glm::dmat3 p;  // columns
};

glm::dvec3 linearPart(const glm::dvec4& c) { return {-c[3], -c[1], c[2]}; }

double asymmetry(const Grid& g, const glm::ivec3& res, const glm::ivec3& centre, const Symmetry& s) {
  double worst = 0.0;
  forEachCube(res, [&](const glm::ivec3& c) {
    const glm::ivec3 image = centre + glm::ivec3(glm::round(s.p * glm::dvec3(c - centre)));
    for (int channel = 0; channel < 3; ++channel) {
      const glm::dvec4 here = cubeOf(g, res, c, channel), there = cubeOf(g, res, image, channel);
      worst = std::max(worst, std::abs(there[0] - here[0]));
      const glm::dvec3 b = s.p * linearPart(here), bImage = linearPart(there);
      for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(bImage[i] - b[i]));
    }
  });
  return worst;
}

const Symmetry kMirrorX{"mirror x", glm::dmat3(-1, 0, 0, 0, 1, 0, 0, 0, 1)};
const Symmetry kMirrorY{"mirror y", glm::dmat3(1, 0, 0, 0, -1, 0, 0, 0, 1)};
const Symmetry kMirrorZ{"mirror z", glm::dmat3(1, 0, 0, 0, 1, 0, 0, 0, -1)};
const Symmetry kSwapXY{"swap x,y", glm::dmat3(0, 1, 0, 1, 0, 0, 0, 0, 1)};
const Symmetry kRotateZ{"90 degrees about z", glm::dmat3(0, 1, 0, -1, 0, 0, 0, 0, 1)};
const Symmetry kRotateX{"90 degrees about x", glm::dmat3(1, 0, 0, 0, 0, 1, 0, -1, 0)};
const Symmetry kRotateXYZ{"x->y->z->x", glm::dmat3(0, 1, 0, 0, 0, 1, 1, 0, 0)};

const glm::ivec3 kRes11{11, 11, 11};
const glm::ivec3 kCentre11{5, 5, 5};

TEST(TetrahedralPropagation, IsotropicVplKeepsTheCubesSymmetries) {
  TetrahedralRig rig(kRes11, 7);
  rig.run(pointSource(kRes11, kCentre11, true));
  for (const Grid& g : {rig.current(), rig.accumulated()}) {
    ASSERT_GT(maxAbs(g), 0.0);
    for (const Symmetry& s : {kMirrorX, kMirrorY, kMirrorZ, kSwapXY, kRotateZ, kRotateX, kRotateXYZ})
      EXPECT_LE(asymmetry(g, kRes11, kCentre11, s), 1e-5 * maxAbs(g)) << s.name;
  }
}

TEST(TetrahedralPropagation, LobeAlongZKeepsTheSymmetriesAboutZ) {
  TetrahedralRig rig(kRes11, 7);
  rig.run(pointSource(kRes11, kCentre11, false));
  for (const Grid& g : {rig.current(), rig.accumulated()}) {
    for (const Symmetry& s : {kMirrorX, kMirrorY, kSwapXY, kRotateZ})
      EXPECT_LE(asymmetry(g, kRes11, kCentre11, s), 1e-5 * maxAbs(g)) << s.name;
    EXPECT_GT(asymmetry(g, kRes11, kCentre11, kMirrorZ), 0.1 * maxAbs(g)) << "the light goes up";
  }
}

}  // namespace
}  // namespace lpvlab
