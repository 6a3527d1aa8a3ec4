#pragma once
// Deterministic quadrature over the unit sphere: Gauss-Legendre in cos(theta) times the midpoint
// rule in phi. Exact (to rounding) for polynomials in (x, y, z) of degree < 2 * nodes, which
// covers products of low-order SH; for the clamped cosine's kink, many nodes give ~1e-6.

#include <cmath>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace lpvlab::testing {

// Gauss-Legendre nodes and weights on [-1, 1] by Newton iteration on P_n.
inline void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double step = p1 / dp;
      t -= step;
      if (std::abs(step) < 1e-15) {
        x[i] = t;
        w[i] = 2.0 / ((1.0 - t * t) * dp * dp);
        break;
      }
    }
  }
}

inline double integrateSphere(const std::function<double(const glm::dvec3&)>& f, int thetaNodes,
                              int phiNodes) {
  std::vector<double> x, w;
  gaussLegendre(thetaNodes, x, w);
  double sum = 0.0;
  for (int i = 0; i < thetaNodes; ++i) {
    const double z = x[i], r = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int j = 0; j < phiNodes; ++j) {
      const double phi = 2.0 * M_PI * (j + 0.5) / phiNodes;
      sum += w[i] * (2.0 * M_PI / phiNodes) * f({r * std::cos(phi), r * std::sin(phi), z});
    }
  }
  return sum;
}

}  // namespace lpvlab::testing
