#pragma once
// Helpers of the propagation tests at any SH order (grid_test_support.h has the order-1 ones): a
// grid of (order + 1)^2 coefficients per channel in grid.glsl's layout, its flux, point sources,
// and the cube's symmetries checked by evaluating the SH functions in many directions (so any
// order works without rotating coefficients).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "grid_test_support.h"

namespace lpvlab::test {

struct OrderGrid {
  glm::ivec3 res;
  int coefficients;
  int cells() const { return shared::cellCount(res); }
  std::size_t floats() const { return std::size_t(3) * coefficients * cells(); }
  std::size_t at(const glm::ivec3& cell, int channel, int k) const {
    return std::size_t(shared::coefficientIndex(channel, k, coefficients, shared::cellIndex(cell, res), cells()));
  }
  // The SH function of `channel` in `cell` at unit direction w.
  double evaluate(const Grid& g, const glm::ivec3& cell, int channel, const glm::dvec3& w) const {
    double sum = 0.0;
    for (int k = 0; k < coefficients; ++k) sum += g[at(cell, channel, k)] * shared::shBasisAt(k, w);
    return sum;
  }
};

inline OrderGrid orderGrid(const glm::ivec3& res, int order) {
  return {res, shared::shCoefficientCount(order)};
}

// Total flux (W, over RGB) of the cells `include` accepts (all by default).
inline double flux(const Grid& g, const OrderGrid& o,
                   const std::function<bool(const glm::ivec3&)>& include = nullptr) {
  double sum = 0.0;
  forEachCell(o.res, [&](const glm::ivec3& c) {
    if (include && !include(c)) return;
    for (int channel = 0; channel < 3; ++channel) sum += shared::shIntegralOfC0(g[o.at(c, channel, 0)]);
  });
  return sum;
}

// One cell holding, per channel (kChannelFlux), an isotropic intensity (c0 only) or a Lambertian
// VPL's lobe Phi / pi * cosLobe(n) at the grid's order.
inline Grid orderSource(const OrderGrid& o, const glm::ivec3& cell, bool isotropic,
                        const glm::dvec3& n = {0, 0, 1}) {
  Grid g(o.floats(), 0.0f);
  for (int channel = 0; channel < 3; ++channel) {
    const double phi = kChannelFlux[channel];
    for (int k = 0; k < o.coefficients; ++k)
      g[o.at(cell, channel, k)] = float(isotropic ? (k == 0 ? phi / (2.0 * std::sqrt(M_PI)) : 0.0)
                                                  : phi / M_PI * shared::shCosineLobeAt(k, n));
  }
  return g;
}

// Largest |difference| between a grid and its image under the symmetry P about `centre`: the
// function f of cell c must equal, at every direction w, the function of cell P c at P w. 64
// directions (a Fibonacci sphere) determine an SH function of order <= 3.
inline double asymmetry(const Grid& g, const OrderGrid& o, const glm::ivec3& centre, const Symmetry& s) {
  std::vector<glm::dvec3> directions;
  const int n = 64;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
    const double phi = M_PI * (3.0 - std::sqrt(5.0)) * i;
    directions.push_back({r * std::cos(phi), r * std::sin(phi), z});
  }
  double worst = 0.0;
  forEachCell(o.res, [&](const glm::ivec3& c) {
    const glm::ivec3 image = centre + glm::ivec3(glm::round(s.p * glm::dvec3(c - centre)));
    if (!shared::cellInside(image, o.res)) {
      ADD_FAILURE() << s.name << " maps cell (" << c.x << "," << c.y << "," << c.z << ") out of the grid";
      return;
    }
    for (int channel = 0; channel < 3; ++channel)
      for (const glm::dvec3& w : directions)
        worst = std::max(worst, std::abs(o.evaluate(g, image, channel, s.p * w) - o.evaluate(g, c, channel, w)));
  });
  return worst;
}

}  // namespace lpvlab::test
