// Standard propagation ("standard", shaders/propagation/standard_gather.comp) on hand-made grids,
// against what its normalisation (shaders/propagation/standard_faces.glsl) implies:
//   - a cell sends its flux through the 30 faces of its 6 neighbours, which tile the sphere, so
//     without the clamp max(0, I) it sends exactly its flux (sum of Omega_f I(w_f) over the faces
//     of a linear I is 4 pi times its mean: the faces come in opposite pairs); the clamp can only
//     add, and for cells holding sums of clamped-cosine lobes (all that injection and
//     propagation ever store) by at most a factor computed below;
//   - the grid's symmetries are kept;
//   - the GPU kernel is the double-precision C++ of the same shared GLSL, gathered the same way.

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/solid_angle.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

constexpr int kCoefficients = 4;
using Grid = std::vector<float>;  // grid.glsl layout, 3 channels, 4 coefficients

// The standard strategy, created as an experiment creates it, on its own light grid.
class PropagationRig {
public:
  PropagationRig(const glm::ivec3& resolution, int iterations) {
    test::glTestContext();
    table_.insert("iterations", iterations);
    Params params(table_, "propagation test", "propagation");
    strategy_ = Registry<PropagationStrategy>::instance().create(params, "standard");
    params.finish();
    geometry_ = GridGeometry{glm::vec3(0.0f), 1.0f, resolution};
    Requirements requirements;
    strategy_->declare(requirements);
    strategy_->prepare(shaders_, geometry_, requirements);
    grid_ = LightGrid(geometry_, requirements.shOrder);
  }

  // Sets current and accumulated (accumulated = current unless given).
  void load(const Grid& current, const Grid* accumulated = nullptr) {
    grid_.current.upload(current.data(), current.size() * sizeof(float));
    const Grid& acc = accumulated ? *accumulated : current;
    grid_.accumulated.upload(acc.data(), acc.size() * sizeof(float));
  }
  void propagate() {
    Frame frame{.gbuffer = gbuffer_, .lightMaps = lightMaps_, .lightGrid = grid_, .indirect = indirect_};
    strategy_->propagate(frame);
    checkGl("propagation test");
  }
  Grid current() const { return download(grid_.current); }
  Grid accumulated() const { return download(grid_.accumulated); }
  PropagationStrategy& strategy() { return *strategy_; }

private:
  Grid download(const gl::Buffer& buffer) const {
    Grid data(grid_.floatsPerGrid());
    buffer.download(data.data(), data.size() * sizeof(float));
    return data;
  }
  toml::table table_;
  ShaderCompiler shaders_;
  std::unique_ptr<PropagationStrategy> strategy_;
  GridGeometry geometry_;
  LightGrid grid_;
  GBuffer gbuffer_;        // propagation reads none of these
  LightMaps lightMaps_;
  gl::Texture indirect_;
};

int cells(const glm::ivec3& res) { return shared::cellCount(res); }

std::size_t at(const glm::ivec3& res, const glm::ivec3& cell, int channel, int k) {
  return std::size_t(shared::coefficientIndex(channel, k, kCoefficients,
                                              shared::cellIndex(cell, res), cells(res)));
}

glm::dvec4 cellOf(const Grid& g, const glm::ivec3& res, const glm::ivec3& cell, int channel) {
  glm::dvec4 c;
  for (int k = 0; k < kCoefficients; ++k) c[k] = g[at(res, cell, channel, k)];
  return c;
}

void forEachCell(const glm::ivec3& res, const std::function<void(const glm::ivec3&)>& f) {
  for (int z = 0; z < res.z; ++z)
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) f({x, y, z});
}

// Total flux (W, summed over RGB): sum of shIntegral over cells, optionally over some cells.
double flux(const Grid& g, const glm::ivec3& res,
            const std::function<bool(const glm::ivec3&)>& include = nullptr) {
  double sum = 0.0;
  forEachCell(res, [&](const glm::ivec3& c) {
    if (include && !include(c)) return;
    for (int channel = 0; channel < 3; ++channel) sum += shared::shIntegral(cellOf(g, res, c, channel));
  });
  return sum;
}

double maxAbs(const Grid& g) {
  double m = 0.0;
  for (float v : g) m = std::max(m, double(std::abs(v)));
  return m;
}

bool allFinite(const Grid& g) {
  return std::all_of(g.begin(), g.end(), [](float v) { return std::isfinite(v); });
}

const glm::ivec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

// What cell coefficients `c` send into the neighbour one step along `d`: the shared GLSL.
glm::dvec4 sent(const glm::dvec4& c, const glm::ivec3& d) {
  static const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  return shared::propagateToNeighbour(c, glm::dvec3(d), angles.farFace, angles.sideFace);
}

// Per-channel flux of the test sources (W): distinct, so channels can't be mixed up unnoticed.
const double kChannelFlux[3] = {1.0, 0.5, 0.25};
double injectedFlux() { return kChannelFlux[0] + kChannelFlux[1] + kChannelFlux[2]; }

// One cell holding, per channel, Phi / pi * cosLobe(n) (a Lambertian VPL, as rsm_vpl injects) or,
// with isotropic, only c0 such that shIntegral = Phi.
Grid pointSource(const glm::ivec3& res, const glm::ivec3& cell, bool isotropic,
                 const glm::dvec3& n = {0, 0, 1}) {
  Grid g(std::size_t(3) * kCoefficients * cells(res), 0.0f);
  for (int channel = 0; channel < 3; ++channel) {
    const double phi = kChannelFlux[channel];
    const glm::dvec4 c = isotropic ? glm::dvec4(phi / (2.0 * std::sqrt(M_PI)), 0, 0, 0)
                                   : phi / M_PI * shared::shCosineLobe(n);
    for (int k = 0; k < kCoefficients; ++k) g[at(res, cell, channel, k)] = float(c[k]);
  }
  return g;
}

// The largest factor by which one propagation step can multiply a cell's flux, over cells
// holding one clamped-cosine lobe Phi / pi * cosLobe(n), maximised over n (sampled densely).
// A cell holding a non-negative sum of such lobes sends at most this factor times its flux too
// (max(0, a + b) <= max(0, a) + max(0, b)). Without the clamp the factor is exactly 1.
double maxStepGain() {
  double gain = 1.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
    const double phi = M_PI * (3.0 - std::sqrt(5.0)) * i;
    const glm::dvec4 lobe = shared::shCosineLobe({r * std::cos(phi), r * std::sin(phi), z}) / M_PI;
    double out = 0.0;
    for (const glm::ivec3& d : kAxes) out += shared::shIntegral(sent(lobe, d));
    gain = std::max(gain, out);
  }
  return gain;
}

// ---- a. symmetries ----------------------------------------------------------------------------

// A symmetry of the cube: the signed permutation P acting on cell offsets from `centre` and on
// directions. An order-1 SH function a + b.w in cell c maps to a + (P b).w in cell P c; with
// (c0, c1, c2, c3) = (a, -y, z, -x) (up to the basis' constants), b = (-c3, -c1, c2).
struct Symmetry {
  std::string name;
  glm::dmat3 p;  // columns
};

glm::dvec3 linearPart(const glm::dvec4& c) { return {-c[3], -c[1], c[2]}; }

// Largest |difference| between the grid and its image under the symmetry.
double asymmetry(const Grid& g, const glm::ivec3& res, const glm::ivec3& centre, const Symmetry& s) {
  double worst = 0.0;
  forEachCell(res, [&](const glm::ivec3& c) {
    const glm::ivec3 image = centre + glm::ivec3(glm::round(s.p * glm::dvec3(c - centre)));
    if (!shared::cellInside(image, res)) {
      ADD_FAILURE() << s.name << " maps cell (" << c.x << "," << c.y << "," << c.z << ") out of the grid";
      return;
    }
    for (int channel = 0; channel < 3; ++channel) {
      const glm::dvec4 here = cellOf(g, res, c, channel), there = cellOf(g, res, image, channel);
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
const Symmetry kSwapYZ{"swap y,z", glm::dmat3(1, 0, 0, 0, 0, 1, 0, 1, 0)};
const Symmetry kSwapXZ{"swap x,z", glm::dmat3(0, 0, 1, 0, 1, 0, 1, 0, 0)};
const Symmetry kRotateXYZ{"x->y->z->x", glm::dmat3(0, 1, 0, 0, 0, 1, 1, 0, 0)};

const glm::ivec3 kRes15{15, 15, 15};
const glm::ivec3 kCentre15{7, 7, 7};

TEST(Propagation, LobeAlongZKeepsTheMirrorsOfXAndY) {
  PropagationRig rig(kRes15, 5);
  rig.load(pointSource(kRes15, kCentre15, false));
  rig.propagate();
  for (const Grid& g : {rig.current(), rig.accumulated()}) {
    const double tolerance = 1e-5 * maxAbs(g);
    ASSERT_TRUE(allFinite(g));
    EXPECT_LE(asymmetry(g, kRes15, kCentre15, kMirrorX), tolerance);
    EXPECT_LE(asymmetry(g, kRes15, kCentre15, kMirrorY), tolerance);
    EXPECT_LE(asymmetry(g, kRes15, kCentre15, kSwapXY), tolerance);  // x and y alike for a +z lobe
    // ... but not z: the light goes up. (Shows the check can tell an asymmetric grid.)
    EXPECT_GT(asymmetry(g, kRes15, kCentre15, kMirrorZ), 0.1 * maxAbs(g));
    const double up = flux(g, kRes15, [](const glm::ivec3& c) { return c.z > 7; });
    const double down = flux(g, kRes15, [](const glm::ivec3& c) { return c.z < 7; });
    EXPECT_GT(up, 2.0 * down) << "a +z lobe sends its light up";
  }
}

TEST(Propagation, IsotropicSourceKeepsEveryMirrorAndAxisPermutation) {
  PropagationRig rig(kRes15, 5);
  rig.load(pointSource(kRes15, kCentre15, true));
  rig.propagate();
  for (const Grid& g : {rig.current(), rig.accumulated()}) {
    const double tolerance = 1e-5 * maxAbs(g);
    ASSERT_TRUE(allFinite(g));
    ASSERT_GT(maxAbs(g), 0.0);
    for (const Symmetry& s : {kMirrorX, kMirrorY, kMirrorZ, kSwapXY, kSwapYZ, kSwapXZ, kRotateXYZ})
      EXPECT_LE(asymmetry(g, kRes15, kCentre15, s), tolerance) << s.name;
  }
}

// ---- b. energy per iteration and the flux crossing a closed shell ------------------------------

// Chebyshev distance from the source cell: the shell of radius R bounds the cells within R.
int chebyshev(const glm::ivec3& c) {
  const glm::ivec3 d = glm::abs(c - kCentre15);
  return std::max({d.x, d.y, d.z});
}

struct ShellFlow {
  double outward = 0.0;  // from cells within the shell to cells outside it
  double inward = 0.0;   // from outside to within
  double gainInside = 0.0;  // what the clamp added to what the cells within sent
};

// The flow of one propagation step whose source grid is `g`, in double precision.
ShellFlow shellFlow(const Grid& g, int radius) {
  ShellFlow flow;
  forEachCell(kRes15, [&](const glm::ivec3& c) {
    const bool inside = chebyshev(c) <= radius;
    for (int channel = 0; channel < 3; ++channel) {
      const glm::dvec4 coefficients = cellOf(g, kRes15, c, channel);
      double sentTotal = 0.0;
      for (const glm::ivec3& d : kAxes) {
        const double f = shared::shIntegral(sent(coefficients, d));
        sentTotal += f;
        const glm::ivec3 target = c + d;
        if (!shared::cellInside(target, kRes15)) continue;
        const bool targetInside = chebyshev(target) <= radius;
        if (inside && !targetInside) flow.outward += f;
        if (!inside && targetInside) flow.inward += f;
      }
      if (inside) flow.gainInside += sentTotal - shared::shIntegral(coefficients);
    }
  });
  return flow;
}

void energyAndShell(bool isotropic) {
  const int iterations = 6;  // from the centre of 15^3, light reaches the grid's edge at step 7
  const int radius = 3;
  const double phi = injectedFlux();
  const double gMax = maxStepGain();
  auto inside = [&](const glm::ivec3& c) { return chebyshev(c) <= radius; };

  PropagationRig rig(kRes15, 1);  // one step per call
  std::vector<Grid> steps{pointSource(kRes15, kCentre15, isotropic)};
  rig.load(steps[0]);
  for (int k = 1; k <= iterations; ++k) {
    rig.propagate();
    steps.push_back(rig.current());
  }
  // The same as one call of `iterations` steps.
  PropagationRig whole(kRes15, iterations);
  whole.load(steps[0]);
  whole.propagate();
  const Grid wholeCurrent = whole.current();
  const double tol = 1e-6 * maxAbs(steps.back());
  for (std::size_t i = 0; i < wholeCurrent.size(); ++i)
    ASSERT_NEAR(wholeCurrent[i], steps.back()[i], tol) << "float " << i;

  std::cout << "[ propagation ] " << (isotropic ? "isotropic" : "+z cosine-lobe")
            << " source, injected " << phi << " W; largest clamp gain per step " << std::setprecision(6)
            << gMax << "\n"
            << "[ propagation ] " << std::setw(3) << "it" << std::setw(11) << "grid flux"
            << std::setw(11) << "/injected" << "  shell R=" << radius << ":" << std::setw(11)
            << "out" << std::setw(11) << "in" << std::setw(11) << "net" << std::setw(11)
            << "cumul.net" << std::setw(14) << "clamp gain in" << std::setw(13) << "flux in"
            << "\n";
  double net = 0.0, gainInside = 0.0;
  double inside0 = flux(steps[0], kRes15, inside);
  EXPECT_NEAR(inside0, phi, 1e-6 * phi);
  for (int k = 1; k <= iterations; ++k) {
    const Grid& before = steps[k - 1];
    const Grid& after = steps[k];
    ASSERT_TRUE(allFinite(after)) << "iteration " << k;
    const double total = flux(after, kRes15), totalBefore = flux(before, kRes15);
    const ShellFlow flow = shellFlow(before, radius);
    net += flow.outward - flow.inward;
    gainInside += flow.gainInside;
    const double insideNow = flux(after, kRes15, inside);
    std::cout << "[ propagation ] " << std::setw(3) << k << std::fixed << std::setprecision(6)
              << std::setw(11) << total << std::setw(11) << total / phi << "            "
              << std::setw(11) << flow.outward << std::setw(11) << flow.inward << std::setw(11)
              << flow.outward - flow.inward << std::setw(11) << net << std::setw(14) << gainInside
              << std::setw(13) << insideNow << "\n"
              << std::defaultfloat;

    // The clamp only adds, by at most gMax per step; nothing has reached the grid's edge yet.
    EXPECT_GE(total, totalBefore * (1.0 - 1e-5)) << "iteration " << k;
    EXPECT_LE(total, totalBefore * gMax * (1.0 + 1e-5)) << "iteration " << k;
    EXPECT_LE(total, phi * std::pow(gMax, k) * (1.0 + 1e-5)) << "iteration " << k;
    if (isotropic && k == 1) {
      EXPECT_NEAR(total, phi, 1e-5 * phi) << "no clamp: exactly conserved";
    }

    // Light moves one cell per step: it reaches the shell's cells at step R and crosses after.
    EXPECT_GE(flow.inward, 0.0);
    if (k <= radius) {
      EXPECT_EQ(flow.outward, 0.0) << "iteration " << k;
    } else {
      EXPECT_GT(flow.outward, 1e-3 * phi) << "iteration " << k;
    }
    if (k <= radius + 1) {
      EXPECT_EQ(flow.inward, 0.0) << "iteration " << k;
    }

    // Conservation across the closed shell: the flux within it changes by what the clamp added
    // there minus the net flux out through it (the GPU's grid against the C++ flow).
    EXPECT_NEAR(insideNow, inside0 + gainInside - net, 1e-5 * phi) << "iteration " << k;
    // Hence the cumulative net outflow is bounded by what was injected plus what the clamp added
    // within the shell (the flux within is non-negative: every cell is a sum of cosine lobes).
    EXPECT_LE(net, (phi + gainInside) * (1.0 + 1e-5)) << "iteration " << k;
    EXPECT_GE(insideNow, 0.0);
  }
}

TEST(Propagation, EnergyPerIterationAndFluxThroughAShellFromALobe) { energyAndShell(false); }
TEST(Propagation, EnergyPerIterationAndFluxThroughAShellFromAnIsotropicSource) {
  energyAndShell(true);
}

// ---- c. zero and very many iterations ---------------------------------------------------------

TEST(Propagation, ZeroIterationsLeaveTheGridAsInjected) {
  PropagationRig rig(kRes15, 0);
  EXPECT_EQ(rig.strategy().iterations(), 0);
  const Grid injected = pointSource(kRes15, kCentre15, false, glm::normalize(glm::dvec3(1, -2, 3)));
  rig.load(injected);
  rig.propagate();
  EXPECT_EQ(rig.current(), injected);
  EXPECT_EQ(rig.accumulated(), injected);
}

TEST(Propagation, AThousandIterationsStayFiniteAndLoseLightAtTheEdge) {
  const glm::ivec3 res{7, 7, 7};
  PropagationRig rig(res, 1000);
  rig.load(pointSource(res, {3, 3, 3}, false, glm::normalize(glm::dvec3(1, 2, 3))));
  rig.propagate();
  const Grid current = rig.current(), accumulated = rig.accumulated();
  ASSERT_TRUE(allFinite(current));
  ASSERT_TRUE(allFinite(accumulated));
  const double now = flux(current, res), sum = flux(accumulated, res);
  std::cout << "[ propagation ] 7^3 grid after 1000 iterations: current flux " << now
            << " W, accumulated " << sum << " W (injected " << injectedFlux() << " W)\n";
  EXPECT_GE(now, 0.0);
  EXPECT_LE(now, injectedFlux());
  EXPECT_LT(now, 1e-6 * injectedFlux()) << "light leaves a 7^3 grid within a few steps";
  // Accumulated: the light that passed through the cells on its way out; finite and positive.
  EXPECT_GT(sum, injectedFlux());
}

// ---- d. the kernel against the double-precision C++ ------------------------------------------

TEST(Propagation, GpuStepMatchesTheSharedCppGather) {
  const glm::ivec3 res{6, 5, 4};  // not multiples of the 4^3 work group, nor a cube
  const std::size_t n = std::size_t(3) * kCoefficients * cells(res);
  std::mt19937 random(12345);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  Grid current(n), accumulated(n);
  for (float& v : current) v = uniform(random);
  for (float& v : accumulated) v = uniform(random);

  PropagationRig rig(res, 1);
  rig.load(current, &accumulated);
  rig.propagate();
  const Grid gpuCurrent = rig.current(), gpuAccumulated = rig.accumulated();

  Grid expectedCurrent(n, 0.0f), expectedAccumulated = accumulated;
  forEachCell(res, [&](const glm::ivec3& cell) {
    for (int channel = 0; channel < 3; ++channel) {
      glm::dvec4 gathered(0.0);
      for (const glm::ivec3& d : kAxes) {
        const glm::ivec3 neighbour = cell - d;  // sends along d into `cell`
        if (!shared::cellInside(neighbour, res)) continue;  // nothing comes from outside
        gathered += sent(cellOf(current, res, neighbour, channel), d);
      }
      for (int k = 0; k < kCoefficients; ++k) {
        expectedCurrent[at(res, cell, channel, k)] = float(gathered[k]);
        expectedAccumulated[at(res, cell, channel, k)] += float(gathered[k]);
      }
    }
  });
  const double tolerance = 1e-5 * maxAbs(expectedCurrent);
  const double toleranceAccumulated = 1e-5 * maxAbs(expectedAccumulated);
  int bad = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::abs(gpuCurrent[i] - expectedCurrent[i]) > tolerance && bad++ < 5)
      ADD_FAILURE() << "current[" << i << "]: GPU " << gpuCurrent[i] << ", C++ " << expectedCurrent[i];
    if (std::abs(gpuAccumulated[i] - expectedAccumulated[i]) > toleranceAccumulated && bad++ < 5)
      ADD_FAILURE() << "accumulated[" << i << "]: GPU " << gpuAccumulated[i] << ", C++ "
                    << expectedAccumulated[i];
  }
  EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace lpvlab
