// Automatic differentiation against central differences on one problem: standard propagation of
// one Lambertian VPL on a 5^3 grid, as a function of its constants (far and side face solid
// angles, damping). The double-precision C++ of the transfer (standard_faces.glsl's face
// directions, normals and SH functions, which are parameter-free) is written once, templated on
// the scalar, so that it runs on ceres::Jet (AD) as well as on double: an independent model of the
// one problem. (The kernels themselves run on lpvlab's Dual through whole frames, checked against
// central differences in frame_derivatives_test.cpp; shared.h cannot take a ceres::Jet, which
// GLM's vectors cannot hold: framework/math/dual.h.)
// Checked: the C++ model equals the GL kernel (float32) run with the same constants; the AD
// Jacobian equals central differences of the C++ (double) and of the GL kernel (float32, step
// 1e-3 as `lpvlab fit` uses); and Ceres fits with either derivative recover the same constants.

#include <cmath>

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include "support/propagation_rig.h"

namespace lpvlab {
namespace {

using test::Grid;

const glm::ivec3 kRes(5);
constexpr int kIterations = 4;

Grid injected() { return test::pointSource(kRes, {2, 2, 1}, false, glm::normalize(glm::dvec3(0.3, 0.2, 1.0))); }

// Standard propagation (gather: each cell receives from its six face neighbours through the five
// faces not shared with the source), order 1, three channels; returns the accumulated grid.
template <class T>
std::vector<T> propagateModel(const Grid& start, T farFace, T sideFace, T damping) {
  std::vector<T> current(start.begin(), start.end()), accumulated = current;
  for (int it = 0; it < kIterations; ++it) {
    std::vector<T> next(current.size(), T(0.0));
    test::forEachCell(kRes, [&](const glm::ivec3& cell) {
      for (const glm::ivec3& d : test::kAxes) {
        const glm::ivec3 source = cell - d;
        if (glm::any(glm::lessThan(source, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(source, kRes)))
          continue;
        for (int channel = 0; channel < 3; ++channel)
          for (int f = 0; f < shared::STANDARD_FACES; ++f) {
            const glm::dvec3 toFace = shared::standardFaceDirection(glm::dvec3(d), f);
            const glm::dvec3 normal = shared::standardFaceNormal(glm::dvec3(d), f);
            T intensity(0.0);
            for (int k = 0; k < test::kCoefficients; ++k)
              intensity += current[test::at(kRes, source, channel, k)] * shared::shBasisAt(k, toFace);
            const T flux = damping * (f == 0 ? farFace : sideFace) * (intensity > T(0.0) ? intensity : T(0.0));
            for (int k = 0; k < test::kCoefficients; ++k)
              next[test::at(kRes, cell, channel, k)] += flux / M_PI * shared::shCosineLobeAt(k, normal);
          }
      }
    });
    current = next;
    for (std::size_t i = 0; i < next.size(); ++i) accumulated[i] += next[i];
  }
  return accumulated;
}

Grid propagateGpu(const Grid& start, const double* x) {
  toml::table t = test::iterationsTable(kIterations);
  t.insert("far_face_solid_angle", x[0]);
  t.insert("side_face_solid_angle", x[1]);
  t.insert("damping", x[2]);
  test::PropagationRig rig("standard", kRes, t);
  rig.load(start);
  rig.propagate();
  return rig.accumulated();
}

const double kPublished[3] = {0.40066968, 0.42343135, 1.0};

// d accumulated / d x_j, column-major (one column per parameter).
std::vector<double> jacobianAd(const Grid& start, const double* x) {
  using Jet = ceres::Jet<double, 3>;
  const std::vector<Jet> out = propagateModel(start, Jet(x[0], 0), Jet(x[1], 1), Jet(x[2], 2));
  std::vector<double> j(3 * out.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int p = 0; p < 3; ++p) j[p * out.size() + i] = out[i].v[p];
  return j;
}

template <class F>
std::vector<double> centralDifferences(const F& f, const double* x, double step) {
  std::vector<double> j;
  for (int p = 0; p < 3; ++p) {
    double plus[3] = {x[0], x[1], x[2]}, minus[3] = {x[0], x[1], x[2]};
    const double h = step * std::abs(x[p]);
    plus[p] += h;
    minus[p] -= h;
    const auto a = f(plus), b = f(minus);
    for (std::size_t i = 0; i < a.size(); ++i) j.push_back((double(a[i]) - double(b[i])) / (2.0 * h));
  }
  return j;
}

// max over parameters of |J_a - J_b| / |J_b| (column norms).
double columnError(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size() / 3;
  double worst = 0.0;
  for (int p = 0; p < 3; ++p) {
    double diff = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      diff += std::pow(a[p * n + i] - b[p * n + i], 2);
      norm += std::pow(b[p * n + i], 2);
    }
    worst = std::max(worst, std::sqrt(diff / norm));
  }
  return worst;
}

TEST(AutoDiff, TheTemplatedModelIsTheGlKernel) {
  const Grid start = injected();
  const double x[3] = {0.37, 0.45, 0.9};
  const std::vector<double> model = propagateModel<double>(start, x[0], x[1], x[2]);
  test::expectClose(propagateGpu(start, x), Grid(model.begin(), model.end()), 1e-5, "accumulated");
}

TEST(AutoDiff, AgreesWithCentralDifferences) {
  const Grid start = injected();
  const std::vector<double> ad = jacobianAd(start, kPublished);
  const auto model = [&](const double* x) { return propagateModel<double>(start, x[0], x[1], x[2]); };
  const auto gpu = [&](const double* x) { return propagateGpu(start, x); };
  // In double precision the difference is truncation error only, O(h^2).
  EXPECT_LT(columnError(centralDifferences(model, kPublished, 1e-3), ad), 1e-5);
  // Through the float32 kernel, rounding divided by h dominates; lpvlab fit's step keeps it small.
  const double gpuError = columnError(centralDifferences(gpu, kPublished, 1e-3), ad);
  EXPECT_LT(gpuError, 1e-2);
  RecordProperty("gpu_central_difference_error", std::to_string(gpuError));
  // Ceres's default relative step (1e-6) is what float32 images cannot take.
  const double tinyStepError = columnError(centralDifferences(gpu, kPublished, 1e-6), ad);
  EXPECT_GT(tinyStepError, 10.0 * gpuError);
  RecordProperty("gpu_central_difference_error_step_1e-6", std::to_string(tinyStepError));
}

// Residuals: the accumulated grid against a target grid.
struct ModelResidual {
  const Grid& start;
  const std::vector<double>& target;
  template <class T>
  bool operator()(T const* const* x, T* r) const {
    const std::vector<T> out = propagateModel(start, x[0][0], x[0][1], T(1.0));
    for (std::size_t i = 0; i < out.size(); ++i) r[i] = out[i] - T(target[i]);
    return true;
  }
};

struct GpuResidual {
  const Grid& start;
  const std::vector<double>& target;
  bool operator()(double const* const* x, double* r) const {
    const double all[3] = {x[0][0], x[0][1], 1.0};
    const Grid out = propagateGpu(start, all);
    for (std::size_t i = 0; i < out.size(); ++i) r[i] = out[i] - target[i];
    return true;
  }
};

std::vector<double> fit(ceres::CostFunction* cost) {
  std::vector<double> x = {kPublished[0], kPublished[1]};
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, x.data());
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  EXPECT_EQ(summary.termination_type, ceres::CONVERGENCE) << summary.BriefReport();
  return x;
}

TEST(AutoDiff, FitsWithEitherDerivativeAgree) {
  const Grid start = injected();
  const double truth[2] = {0.33, 0.47};
  const std::vector<double> target = propagateModel<double>(start, truth[0], truth[1], 1.0);
  const int n = int(target.size());

  auto* ad = new ceres::DynamicAutoDiffCostFunction<ModelResidual, 2>(new ModelResidual{start, target});
  ad->AddParameterBlock(2);
  ad->SetNumResiduals(n);
  ceres::NumericDiffOptions step;
  step.relative_step_size = 1e-3;  // lpvlab fit's (fit_problem.h)
  auto* cd = new ceres::DynamicNumericDiffCostFunction<GpuResidual, ceres::CENTRAL>(
      new GpuResidual{start, target}, ceres::TAKE_OWNERSHIP, step);
  cd->AddParameterBlock(2);
  cd->SetNumResiduals(n);

  const std::vector<double> byAd = fit(ad), byCd = fit(cd);
  EXPECT_NEAR(byAd[0], truth[0], 1e-7);  // to Ceres's convergence tolerances
  EXPECT_NEAR(byAd[1], truth[1], 1e-7);
  EXPECT_NEAR(byCd[0], byAd[0], 1e-4);   // float32 kernel against a double target
  EXPECT_NEAR(byCd[1], byAd[1], 1e-4);
  RecordProperty("ad_minus_cd", std::to_string(byAd[0] - byCd[0]) + " " + std::to_string(byAd[1] - byCd[1]));
}

}  // namespace
}  // namespace lpvlab
