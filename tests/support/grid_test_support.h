#pragma once
// Helpers of the tests that run propagation on hand-made light grids (grid.glsl's layout: per
// channel, per coefficient, per cell), in double precision: indexing, the flux a grid holds, point
// sources, comparisons, and the cube's symmetries acting on order-1 grids. The order-1 helpers
// take kCoefficients = 4 coefficients per channel.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "framework/math/shared.h"

namespace lpvlab::test {

using Grid = std::vector<float>;  // grid.glsl layout, 3 channels (or any float buffer)

inline constexpr int kCoefficients = 4;  // order 1
inline const glm::ivec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

inline int cells(const glm::ivec3& res) { return shared::cellCount(res); }

// The index of coefficient k of `channel` in `cell` of an order-1 grid.
inline std::size_t at(const glm::ivec3& res, const glm::ivec3& cell, int channel, int k) {
  return std::size_t(shared::coefficientIndex(channel, k, kCoefficients,
                                              shared::cellIndex(cell, res), cells(res)));
}

inline glm::dvec4 cellOf(const Grid& g, const glm::ivec3& res, const glm::ivec3& cell, int channel) {
  glm::dvec4 c;
  for (int k = 0; k < kCoefficients; ++k) c[k] = g[at(res, cell, channel, k)];
  return c;
}

inline void forEachCell(const glm::ivec3& res, const std::function<void(const glm::ivec3&)>& f) {
  for (int z = 0; z < res.z; ++z)
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) f({x, y, z});
}

// Total flux (W, summed over RGB) of an order-1 grid: sum of shIntegral over cells, optionally
// over some cells.
inline double flux(const Grid& g, const glm::ivec3& res,
                   const std::function<bool(const glm::ivec3&)>& include = nullptr) {
  double sum = 0.0;
  forEachCell(res, [&](const glm::ivec3& c) {
    if (include && !include(c)) return;
    for (int channel = 0; channel < 3; ++channel) sum += shared::shIntegral(cellOf(g, res, c, channel));
  });
  return sum;
}

inline double maxAbs(const Grid& g) {
  double m = 0.0;
  for (float v : g) m = std::max(m, double(std::abs(v)));
  return m;
}

inline double maxDifference(const Grid& a, const Grid& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, double(std::abs(a[i] - b[i])));
  return m;
}

inline bool allFinite(const Grid& g) {
  return std::all_of(g.begin(), g.end(), [](float v) { return std::isfinite(v); });
}

// n floats uniform in [low, high).
inline Grid randomFloats(std::size_t n, std::mt19937& random, float low = -1.0f, float high = 1.0f) {
  std::uniform_real_distribution<float> uniform(low, high);
  Grid v(n);
  for (float& x : v) x = uniform(random);
  return v;
}

// Random blocking: c0 in [0, 1.5], band 1 as large so transmittances
// cover [0, 1] with both clamps and the normal estimate sees every direction.
inline Grid randomGv(const glm::ivec3& gvRes, std::mt19937& random) {
  Grid gv = randomFloats(std::size_t(4) * cells(gvRes), random, -1.0f, 1.0f);
  for (int i = 0; i < cells(gvRes); ++i) gv[i] = 0.75f * (gv[i] + 1.0f);
  return gv;
}

// Random albedo (rho A, A) per GV cell: A in [0, 1) with a fifth of the cells unseen (A = 0),
// rho in [0, 1] per channel.
inline Grid randomAlbedo(const glm::ivec3& gvRes, std::mt19937& random) {
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  Grid albedo(std::size_t(4) * cells(gvRes), 0.0f);
  for (int i = 0; i < cells(gvRes); ++i) {
    if (uniform(random) < 0.2f) continue;
    const float weight = uniform(random);
    for (int c = 0; c < 3; ++c) albedo[4 * i + c] = weight * uniform(random);
    albedo[4 * i + 3] = weight;
  }
  return albedo;
}

// Blocking potential of random surfels for a GV of `gvCells` cells (order 1, 4 floats per cell,
// coefficient-major): c0 in [0, 0.6], the linear part smaller, so that 1 - B ranges over (0, 1]
// and the clamp sometimes acts.
inline Grid randomBlocking(int gvCells, std::mt19937& random) {
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  Grid blocking(std::size_t(4) * gvCells);
  for (int i = 0; i < gvCells; ++i) {
    blocking[i] = 0.3f * (uniform(random) + 1.0f);
    for (int k = 1; k < 4; ++k) blocking[std::size_t(k) * gvCells + i] = 0.4f * uniform(random);
  }
  return blocking;
}

// Every float of `gpu` within relative * maxAbs(expected) of `expected` (the first few misses
// reported, named `what`).
inline void expectClose(const Grid& gpu, const Grid& expected, double relative, const char* what) {
  const double tolerance = relative * maxAbs(expected);
  int bad = 0;
  for (std::size_t i = 0; i < gpu.size(); ++i)
    if (std::abs(gpu[i] - expected[i]) > tolerance && bad++ < 5)
      ADD_FAILURE() << what << "[" << i << "]: GPU " << gpu[i] << ", C++ " << expected[i];
  EXPECT_EQ(bad, 0) << what;
}

// ---- sources ------------------------------------------------------------------------------------

// Per-channel flux of the test sources (W): distinct, so channels can't be mixed up unnoticed.
inline const double kChannelFlux[3] = {1.0, 0.5, 0.25};
inline double injectedFlux() { return kChannelFlux[0] + kChannelFlux[1] + kChannelFlux[2]; }

// An order-1 grid with one cell holding, per channel, Phi / pi * cosLobe(n) (a Lambertian VPL, as
// rsm_vpl injects) or, with isotropic, only c0 such that shIntegral = Phi.
inline Grid pointSource(const glm::ivec3& res, const glm::ivec3& cell, bool isotropic,
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

// ---- symmetries -----------------------------------------------------------------------------------

// A symmetry of the cube: the signed permutation P acting on cell offsets from a centre cell and
// on directions. An order-1 SH function a + b.w in cell c maps to a + (P b).w in cell P c; with
// (c0, c1, c2, c3) = (a, -y, z, -x) (up to the basis' constants), b = (-c3, -c1, c2).
struct Symmetry {
  std::string name;
  glm::dmat3 p;  // columns
};

inline glm::dvec3 linearPart(const glm::dvec4& c) { return {-c[3], -c[1], c[2]}; }

// Largest |difference| between an order-1 grid and its image under the symmetry about `centre`.
inline double asymmetry(const Grid& g, const glm::ivec3& res, const glm::ivec3& centre,
                        const Symmetry& s) {
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

inline const Symmetry kMirrorX{"mirror x", glm::dmat3(-1, 0, 0, 0, 1, 0, 0, 0, 1)};
inline const Symmetry kMirrorY{"mirror y", glm::dmat3(1, 0, 0, 0, -1, 0, 0, 0, 1)};
inline const Symmetry kMirrorZ{"mirror z", glm::dmat3(1, 0, 0, 0, 1, 0, 0, 0, -1)};
inline const Symmetry kSwapXY{"swap x,y", glm::dmat3(0, 1, 0, 1, 0, 0, 0, 0, 1)};
inline const Symmetry kSwapYZ{"swap y,z", glm::dmat3(1, 0, 0, 0, 0, 1, 0, 1, 0)};
inline const Symmetry kSwapXZ{"swap x,z", glm::dmat3(0, 0, 1, 0, 1, 0, 1, 0, 0)};
inline const Symmetry kRotateZ{"90 degrees about z", glm::dmat3(0, 1, 0, -1, 0, 0, 0, 0, 1)};
inline const Symmetry kRotateX{"90 degrees about x", glm::dmat3(1, 0, 0, 0, 0, 1, 0, -1, 0)};
inline const Symmetry kRotateXYZ{"x->y->z->x", glm::dmat3(0, 1, 0, 0, 0, 1, 1, 0, 0)};

}  // namespace lpvlab::test
