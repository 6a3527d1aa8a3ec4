// Standard propagation ("standard", shaders/propagation/standard_gather.comp) on hand-made grids,
// against what its normalisation (shaders/propagation/standard_faces.glsl) implies:
//   - a cell sends its flux through the 30 faces of its 6 neighbours, which tile the sphere, so
//     without the clamp max(0, I) it sends exactly its flux (sum of Omega_f I(w_f) over the faces
//     of a linear I is 4 pi times its mean: the faces come in opposite pairs); the clamp can only
//     add, and for cells holding sums of clamped-cosine lobes (all that injection and
//     propagation ever store) by at most a factor computed below; and across a closed shell the
//     flux inside changes by what crosses it (on the GL and the CPU backend);
//   - the grid's symmetries are kept;
//   - the GPU kernel is the double-precision C++ of the same shared GLSL, gathered the same way.

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "framework/math/solid_angle.h"
#include "propagation_rig.h"

namespace lpvlab {
namespace {

using namespace test;

// The standard strategy, created as an experiment creates it, on its own light grid.
PropagationRig standardRig(const glm::ivec3& resolution, int iterations,
                           ComputeBackend backend = ComputeBackend::Gl) {
  return PropagationRig("standard", resolution, iterationsTable(iterations), 1, false, backend);
}

// What cell coefficients `c` send into the neighbour one step along `d`: the shared GLSL.
glm::dvec4 sent(const glm::dvec4& c, const glm::ivec3& d) {
  static const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  return shared::propagateToNeighbour(c, glm::dvec3(d), angles.farFace, angles.sideFace);
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

const glm::ivec3 kRes15{15, 15, 15};
const glm::ivec3 kCentre15{7, 7, 7};

TEST(Propagation, LobeAlongZKeepsTheMirrorsOfXAndY) {
  PropagationRig rig = standardRig(kRes15, 5);
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
  PropagationRig rig = standardRig(kRes15, 5);
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

void energyAndShell(bool isotropic, ComputeBackend backend) {
  const int iterations = 6;  // from the centre of 15^3, light reaches the grid's edge at step 7
  const int radius = 3;
  const double phi = injectedFlux();
  const double gMax = maxStepGain();
  auto inside = [&](const glm::ivec3& c) { return chebyshev(c) <= radius; };

  PropagationRig rig = standardRig(kRes15, 1, backend);  // one step per call
  std::vector<Grid> steps{pointSource(kRes15, kCentre15, isotropic)};
  rig.load(steps[0]);
  for (int k = 1; k <= iterations; ++k) {
    rig.propagate();
    steps.push_back(rig.current());
  }
  // The same as one call of `iterations` steps.
  PropagationRig whole = standardRig(kRes15, iterations, backend);
  whole.load(steps[0]);
  whole.propagate();
  const Grid wholeCurrent = whole.current();
  const double tol = 1e-6 * maxAbs(steps.back());
  for (std::size_t i = 0; i < wholeCurrent.size(); ++i)
    ASSERT_NEAR(wholeCurrent[i], steps.back()[i], tol) << "float " << i;

  std::cout << "[ propagation ] " << (backend == ComputeBackend::Cpu ? "CPU, " : "GL, ")
            << (isotropic ? "isotropic" : "+z cosine-lobe")
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

TEST(Propagation, EnergyPerIterationAndFluxThroughAShellFromALobe) {
  energyAndShell(false, ComputeBackend::Gl);
}
TEST(Propagation, EnergyPerIterationAndFluxThroughAShellFromAnIsotropicSource) {
  energyAndShell(true, ComputeBackend::Gl);
}
// The same on the CPU backend (standard_cpu.h).
TEST(Propagation, EnergyAndFluxThroughAShellFromALobeOnTheCpu) {
  energyAndShell(false, ComputeBackend::Cpu);
}
TEST(Propagation, EnergyAndFluxThroughAShellFromAnIsotropicSourceOnTheCpu) {
  energyAndShell(true, ComputeBackend::Cpu);
}

// ---- c. zero and very many iterations ---------------------------------------------------------

// Zero and a thousand iterations, on both backends.
// Face solid angles above the geometric ones: an isotropic cell sends 6 (far + 4 side) / (4 pi)
// of its flux on per iteration, here 1.5, and the strategy says so in its warnings; with the
// geometric angles it sends exactly its flux and warns of nothing.
TEST(Propagation, FaceSolidAnglesThatGainEnergyAreMeasuredAndFlagged) {
  const glm::ivec3 res{9, 9, 9}, centre{4, 4, 4};
  const double side = 0.42, far = 1.5 * 4.0 * M_PI / 6.0 - 4.0 * side;  // gain 1.5
  toml::table table = iterationsTable(1);
  table.insert("far_face_solid_angle", far);
  table.insert("side_face_solid_angle", side);
  PropagationRig gaining("standard", res, table, 1, false, ComputeBackend::Cpu);
  gaining.load(pointSource(res, centre, true));
  const double injected = flux(gaining.current(), res);
  gaining.propagate();
  EXPECT_NEAR(flux(gaining.current(), res) / injected, 1.5, 1e-5);
  const std::vector<std::string> warnings = gaining.strategy().warnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("multiplies an isotropic cell's light by up to 1.5"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("gains energy"), std::string::npos);

  PropagationRig geometric("standard", res, iterationsTable(1), 1, false, ComputeBackend::Cpu);
  geometric.load(pointSource(res, centre, true));
  geometric.propagate();
  EXPECT_NEAR(flux(geometric.current(), res) / injected, 1.0, 1e-5);
  EXPECT_TRUE(geometric.strategy().warnings().empty());
}

TEST(Propagation, ZeroIterationsLeaveTheGridAsInjected) {
  for (const ComputeBackend backend : {ComputeBackend::Gl, ComputeBackend::Cpu}) {
    PropagationRig rig = standardRig(kRes15, 0, backend);
    EXPECT_EQ(rig.strategy().iterations(), 0);
    const Grid injected = pointSource(kRes15, kCentre15, false, glm::normalize(glm::dvec3(1, -2, 3)));
    rig.load(injected);
    rig.propagate();
    EXPECT_EQ(rig.current(), injected);
    EXPECT_EQ(rig.accumulated(), injected);
  }
}
TEST(Propagation, AThousandIterationsStayFiniteAndLoseLightAtTheEdge) {
  const glm::ivec3 res{7, 7, 7};
  for (const ComputeBackend backend : {ComputeBackend::Gl, ComputeBackend::Cpu}) {
    const char* where = backend == ComputeBackend::Cpu ? "CPU" : "GL";
    PropagationRig rig = standardRig(res, 1000, backend);
    rig.load(pointSource(res, {3, 3, 3}, false, glm::normalize(glm::dvec3(1, 2, 3))));
    rig.propagate();
    const Grid current = rig.current(), accumulated = rig.accumulated();
    ASSERT_TRUE(allFinite(current)) << where;
    ASSERT_TRUE(allFinite(accumulated)) << where;
    const double now = flux(current, res), sum = flux(accumulated, res);
    std::cout << "[ propagation ] " << where << ", 7^3 grid after 1000 iterations: current flux "
              << now << " W, accumulated " << sum << " W (injected " << injectedFlux() << " W)\n";
    EXPECT_GE(now, 0.0) << where;
    EXPECT_LE(now, injectedFlux()) << where;
    EXPECT_LT(now, 1e-6 * injectedFlux()) << where << ": light leaves a 7^3 grid within a few steps";
    // Accumulated: the light that passed through the cells on its way out; finite and positive.
    EXPECT_GT(sum, injectedFlux()) << where;
  }
}

// ---- d. the kernel against the double-precision C++ ------------------------------------------

TEST(Propagation, GpuStepMatchesTheSharedCppGather) {
  const glm::ivec3 res{6, 5, 4};  // not multiples of the 4^3 work group, nor a cube
  const std::size_t n = std::size_t(3) * kCoefficients * cells(res);
  std::mt19937 random(12345);
  const Grid current = randomFloats(n, random), accumulated = randomFloats(n, random);

  PropagationRig rig = standardRig(res, 1);
  rig.load(current, accumulated);
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
  expectClose(gpuCurrent, expectedCurrent, 1e-5, "current");
  expectClose(gpuAccumulated, expectedAccumulated, 1e-5, "accumulated");
}

}  // namespace
}  // namespace lpvlab
