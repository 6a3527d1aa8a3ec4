#include "framework/fit/fit_problem.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "framework/core/error.h"
#include "framework/fit/fit_covariance.h"

namespace lpvlab {

namespace {

// The magnitude that makes a parameter's step and its Jacobian column unit-free.
double magnitude(const FitParameter& p, double x) {
  const double m = std::max(std::abs(x), std::abs(p.initial));
  return m > 0.0 ? m : 1.0;
}

// All views' residuals as one block of one-scalar parameter blocks (one per fitted parameter,
// so each can have bounds and be held constant), differentiated through the frames on dual
// numbers where `automatic[j]`, else by bounded central differences (fit_problem.h). An Error of
// the pipeline is kept and rethrown after the solve: Ceres sees a failed evaluation, never an
// exception.
class ImageCost final : public ceres::CostFunction {
public:
  ImageCost(FitEvaluator& evaluator, std::vector<bool> automatic)
      : evaluator_(evaluator), automatic_(std::move(automatic)) {
    set_num_residuals(evaluator.residualCount());
    for (std::size_t i = 0; i < evaluator.spec().parameters.size(); ++i)
      mutable_parameter_block_sizes()->push_back(1);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    try {
      evaluate(parameters, residuals, jacobians);
      return true;
    } catch (const std::exception&) {
      if (!error_) error_ = std::current_exception();
      return false;
    }
  }

  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

private:
  // Ceres evaluates the same point several times (with and without the Jacobian, and again
  // for the covariance): the last point's residuals and Jacobian columns are kept.
  void evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
    const std::vector<FitParameter>& spec = evaluator_.spec().parameters;
    std::vector<double> x(spec.size());
    for (std::size_t j = 0; j < x.size(); ++j) x[j] = parameters[j][0];
    const std::size_t n = std::size_t(num_residuals());
    if (x != x_) {
      x_.clear();  // until the residuals are complete
      r_.resize(n);
      evaluator_.residuals(x, r_.data());
      columns_.assign(x.size(), {});
      x_ = x;
    }
    std::copy(r_.begin(), r_.end(), residuals);
    if (!jacobians) return;
    for (std::size_t j = 0; j < x.size(); ++j) {
      if (!jacobians[j]) continue;
      if (columns_[j].empty()) {
        if (automatic(x, j)) {
          // Every automatic column at once: one pass per view carries up to four.
          std::vector<std::size_t> which;
          for (std::size_t k = 0; k < x.size(); ++k)
            if (automatic(x, k) && columns_[k].empty()) which.push_back(k);
          evaluator_.automaticColumns(x, which, columns_);
        } else {
          columns_[j] = column(x, j);
        }
      }
      std::copy(columns_[j].begin(), columns_[j].end(), jacobians[j]);
    }
  }

  // Whether column j at x is automatic: one the composition carries, with x_j inside its bounds.
  // At a bound the differences are one-sided, into the feasible side, while the dual numbers give
  // the derivative of the kernel's branch at the bound, which at a kink there is the other side's:
  // a face solid angle of 0 folds into the face's flux as max(0, omega I), whose derivative by
  // omega at 0 is 0 whatever the sign of I, where the fit needs max(0, I).
  bool automatic(const std::vector<double>& x, std::size_t j) const {
    const FitParameter& p = evaluator_.spec().parameters[j];
    return automatic_[j] && x[j] > p.lower && x[j] < p.upper;
  }

  std::vector<double> column(const std::vector<double>& x, std::size_t j) const {
    const FitParameter& p = evaluator_.spec().parameters[j];
    const std::size_t n = std::size_t(num_residuals());
    const double step = p.step > 0.0 ? p.step : evaluator_.spec().relativeStep;
    const double h = step * magnitude(p, x[j]);
    const double hi = std::min(x[j] + h, p.upper), lo = std::max(x[j] - h, p.lower);
    std::vector<double> plus = r_, minus = r_, at = x, out(n);
    at[j] = hi;
    if (hi > x[j]) evaluator_.residuals(at, plus.data());
    at[j] = lo;
    if (lo < x[j]) evaluator_.residuals(at, minus.data());
    for (std::size_t i = 0; i < n; ++i) out[i] = (plus[i] - minus[i]) / (hi - lo);
    return out;
  }

  FitEvaluator& evaluator_;
  const std::vector<bool> automatic_;
  mutable std::exception_ptr error_;
  mutable std::vector<double> x_, r_;               // the last point evaluated, its residuals
  mutable std::vector<std::vector<double>> columns_;  // and its Jacobian columns (empty: not yet)
};

// Appends each iteration to the result's log, with the renderings and seconds so far; a resumed
// solve continues `resume`'s numbering, renderings and time and leaves out its iteration 0 (the
// resumed point, already logged).
class LogCallback final : public ceres::IterationCallback {
public:
  LogCallback(const std::vector<double>& x, FitResult& result, const FitEvaluator& evaluator,
              const std::function<void(const FitIteration&)>& onIteration, const FitProgress* resume)
      : x_(x), result_(result), evaluator_(evaluator), onIteration_(onIteration),
        rendersBefore_(evaluator.evaluated().size()), resume_(resume) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (resume_ && s.iteration == 0) return ceres::SOLVER_CONTINUE;
    FitIteration it{(resume_ ? resume_->log.back().iteration : 0) + s.iteration,
                    s.cost,
                    s.gradient_max_norm,
                    s.step_norm,
                    s.step_is_successful,
                    (resume_ ? resume_->seconds : 0.0) + s.cumulative_time_in_seconds,
                    x_,
                    (resume_ ? resume_->renders : 0) + renders(),
                    s.trust_region_radius};
    result_.log.push_back(it);
    if (onIteration_) onIteration_(it);
    return ceres::SOLVER_CONTINUE;
  }

  // The solve's own renderings so far.
  int renders() const { return int(evaluator_.evaluated().size() - rendersBefore_); }

private:
  const std::vector<double>& x_;
  FitResult& result_;
  const FitEvaluator& evaluator_;
  const std::function<void(const FitIteration&)>& onIteration_;
  const std::size_t rendersBefore_;  // e.g. the errors measured before the fit
  const FitProgress* resume_;        // null, or a non-empty log
};

// The residuals and the Jacobian (column j: parameter j) at `x`; the cost function keeps them,
// so Ceres's covariance after this renders nothing new.
void residualsAndJacobian(ImageCost& cost, const std::vector<double>& x, Eigen::VectorXd& residuals,
                          Eigen::MatrixXd& jacobian) {
  const std::size_t n = std::size_t(cost.num_residuals()), p = x.size();
  residuals.resize(Eigen::Index(n));
  jacobian.resize(Eigen::Index(n), Eigen::Index(p));  // column-major: column j is contiguous
  std::vector<const double*> blocks(p);
  std::vector<double*> jacobians(p);
  for (std::size_t j = 0; j < p; ++j) blocks[j] = &x[j], jacobians[j] = jacobian.col(Eigen::Index(j)).data();
  if (!cost.Evaluate(blocks.data(), residuals.data(), jacobians.data())) cost.rethrow();
}

// Marks the parameters along directions the scaled Jacobian does not determine (fit_problem.h);
// returns the singular values, largest first.
std::vector<double> findUndetermined(const FitSpec& spec, const Eigen::MatrixXd& jacobian,
                                     const std::vector<double>& x, std::vector<bool>& undetermined) {
  const std::size_t p = x.size();
  Eigen::MatrixXd columns = jacobian;
  for (std::size_t j = 0; j < p; ++j) columns.col(Eigen::Index(j)) *= magnitude(spec.parameters[j], x[j]);
  // The singular values of J are the square roots of the eigenvalues of J^T J (p x p, small).
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(columns.transpose() * columns);
  std::vector<double> singular;
  for (Eigen::Index k = Eigen::Index(p); k-- > 0;)
    singular.push_back(std::sqrt(std::max(0.0, eigen.eigenvalues()[k])));
  const double largest = singular.empty() ? 0.0 : singular.front();
  undetermined.assign(p, false);
  for (Eigen::Index k = 0; k < Eigen::Index(p); ++k) {
    const double s = std::sqrt(std::max(0.0, eigen.eigenvalues()[k]));
    if (largest > 0.0 && s > spec.rankTolerance * largest) continue;
    for (std::size_t j = 0; j < p; ++j)
      if (std::abs(eigen.eigenvectors()(Eigen::Index(j), k)) > 0.1) undetermined[j] = true;
  }
  return singular;
}

// The sandwich deviations (fit_covariance.h) of the determined parameters, clustered by image
// tiles of the fitted views; NaN for the undetermined.
std::vector<double> sandwichDeviations(const FitEvaluator& evaluator, const Eigen::MatrixXd& jacobian,
                                       const Eigen::VectorXd& residuals, const std::vector<bool>& undetermined) {
  std::vector<std::pair<int, int>> sizes;
  for (const FitView& v : evaluator.views())
    if (!v.heldOut) sizes.emplace_back(v.target.width, v.target.height);
  std::vector<int> cluster;
  const int clusters = tileClusters(sizes, evaluator.spec().tile, cluster);
  std::vector<Eigen::Index> determined;
  for (std::size_t j = 0; j < undetermined.size(); ++j)
    if (!undetermined[j]) determined.push_back(Eigen::Index(j));
  std::vector<double> out(undetermined.size(), std::numeric_limits<double>::quiet_NaN());
  if (determined.empty()) return out;
  Eigen::MatrixXd columns(jacobian.rows(), Eigen::Index(determined.size()));
  for (std::size_t k = 0; k < determined.size(); ++k) columns.col(Eigen::Index(k)) = jacobian.col(determined[k]);
  const Eigen::MatrixXd c = sandwichCovariance(columns, residuals, cluster, clusters);
  for (std::size_t k = 0; k < determined.size(); ++k)
    out[std::size_t(determined[k])] = std::sqrt(std::max(0.0, c(Eigen::Index(k), Eigen::Index(k))));
  return out;
}

}  // namespace

FitProgress resumePoint(const FitProgress& progress) {
  FitProgress point = progress;
  while (point.log.size() > 1 && !point.log.back().successful) point.log.pop_back();
  if (!point.log.empty() && point.log.size() < progress.log.size()) {
    point.renders = point.log.back().renders;
    point.seconds = point.log.back().seconds;
  }
  return point;
}

namespace {

// Ceres counts the iterations of its own solve ("Number of iterations: K."); a resumed fit's are
// `done` more.
std::string withWholeFitIterations(const std::string& message, int done) {
  const std::string label = "Number of iterations: ";
  const auto at = message.find(label);
  if (at == std::string::npos) return message;
  std::size_t end = at + label.size();
  while (end < message.size() && std::isdigit(static_cast<unsigned char>(message[end]))) ++end;
  const std::string digits = message.substr(at + label.size(), end - at - label.size());
  if (digits.empty()) return message;
  const int here = std::stoi(digits);
  return message.substr(0, at) + label + std::to_string(done + here) + " (" + std::to_string(here) +
         " after resuming at iteration " + std::to_string(done) + ")" + message.substr(end);
}

// The solver's options for the iterations left (`done` were; a resumed fit starts from its
// trust region).
ceres::Solver::Options solverOptions(const FitSpec& spec, int done, const FitProgress* resume) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = std::max(0, spec.maxIterations - done);
  options.num_threads = 1;  // one GL context, used from this thread only
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.update_state_every_iteration = true;  // the log records x after each iteration
  // With bounds, Ceres 2.1 follows every trust-region step with a projected Armijo line search
  // (up to 20 trial points, one rendering per view each with bisection). On the LPV's cost, which
  // the injection shift makes step-like, it found no decrease where the step failed (the Sponza
  // fits spent 42 renderings per rejected iteration), and the trust region already shortens a
  // rejected step (and turns it towards the gradient) at one rendering per view. So it is off:
  // steps are projected onto the bounds (Ceres's Plus) and judged by the trust region alone.
  options.max_num_line_search_step_size_iterations = 0;
  const double radius = resume ? resume->log.back().trustRegionRadius : 0.0;
  if (radius > 0.0 && radius <= options.max_trust_region_radius)
    options.initial_trust_region_radius = radius;
  return options;
}

// The determined parameters' standard deviations from Ceres's covariance, scaled by the residual
// variance (NaN for the undetermined, which are held constant from here on).
std::vector<double> standardDeviations(const FitSpec& spec, ceres::Problem& problem,
                                       const std::vector<double*>& blocks, ImageCost& cost,
                                       const FitResult& result) {
  const std::size_t p = blocks.size();
  std::vector<double> stdDev(p, std::numeric_limits<double>::quiet_NaN());
  std::vector<const double*> determined;
  for (std::size_t j = 0; j < p; ++j) {
    if (result.undetermined[j]) problem.SetParameterBlockConstant(blocks[j]);
    else determined.push_back(blocks[j]);
  }
  const long long dof = result.coveredResiduals - (long long)determined.size();
  if (!determined.empty() && dof > 0) {
    ceres::Covariance::Options covarianceOptions;
    covarianceOptions.algorithm_type = ceres::DENSE_SVD;
    covarianceOptions.num_threads = 1;
    ceres::Covariance covariance(covarianceOptions);
    std::vector<std::pair<const double*, const double*>> pairs;
    for (const double* b : determined) pairs.push_back({b, b});
    const bool computed = covariance.Compute(pairs, &problem);
    cost.rethrow();
    if (!computed)
      throw Error(spec.file + ": the covariance of the fitted parameters could not be computed "
                  "(rank-deficient beyond rank_tolerance = " + std::to_string(spec.rankTolerance) +
                  "; raise it)");
    const double variance = 2.0 * result.finalCost / double(dof);
    for (std::size_t j = 0; j < p; ++j) {
      if (result.undetermined[j]) continue;
      double c = 0.0;
      covariance.GetCovarianceBlock(blocks[j], blocks[j], &c);
      stdDev[j] = std::sqrt(std::max(0.0, c * variance));
    }
  }
  return stdDev;
}

}  // namespace

FitResult runFit(FitEvaluator& evaluator, const std::function<void(const FitIteration&)>& onIteration,
                 const FitProgress* progress) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<FitProgress> point;
  if (progress && !progress->log.empty()) point = resumePoint(*progress);
  const FitProgress* resume = point ? &*point : nullptr;
  const FitSpec& spec = evaluator.spec();
  const std::size_t p = spec.parameters.size();
  FitResult result;
  for (const FitParameter& parameter : spec.parameters) result.initial.push_back(parameter.initial);
  std::vector<double> x = result.initial;
  const bool resumed = resume && !resume->log.empty();
  const int done = resumed ? resume->log.back().iteration : 0;
  if (resumed) {
    if (resume->log.back().x.size() != p)
      throw Error(spec.file + ": the progress to resume has " + std::to_string(resume->log.back().x.size()) +
                  " parameter values, the fit " + std::to_string(p));
    x = resume->log.back().x;
    result.log = resume->log;
  }

  result.derivatives = evaluator.automaticRefusals();
  std::vector<bool> automatic;
  for (const std::string& why : result.derivatives) automatic.push_back(why.empty());
  ImageCost cost(evaluator, automatic);
  ceres::Problem::Options problemOptions;
  problemOptions.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problemOptions);
  std::vector<double*> blocks;
  for (double& v : x) blocks.push_back(&v);
  problem.AddResidualBlock(&cost, nullptr, blocks);
  for (std::size_t j = 0; j < p; ++j) {
    if (spec.parameters[j].lower > -1e300) problem.SetParameterLowerBound(blocks[j], 0, spec.parameters[j].lower);
    if (spec.parameters[j].upper < 1e300) problem.SetParameterUpperBound(blocks[j], 0, spec.parameters[j].upper);
  }

  ceres::Solver::Options options = solverOptions(spec, done, resumed ? resume : nullptr);
  LogCallback callback(x, result, evaluator, onIteration, resumed ? resume : nullptr);
  options.callbacks.push_back(&callback);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  cost.rethrow();
  result.values = x;
  result.initialCost = resumed ? resume->log.front().cost : summary.initial_cost;
  result.finalCost = summary.final_cost;
  result.termination = resumed ? withWholeFitIterations(summary.message, done) : summary.message;
  result.converged = summary.termination_type == ceres::CONVERGENCE;

  for (std::size_t j = 0; j < p; ++j)
    result.atBound.push_back(x[j] == spec.parameters[j].lower || x[j] == spec.parameters[j].upper);
  Eigen::VectorXd residuals;
  Eigen::MatrixXd jacobian;
  residualsAndJacobian(cost, x, residuals, jacobian);
  result.singularValues = findUndetermined(spec, jacobian, x, result.undetermined);
  result.sandwichStdDev = sandwichDeviations(evaluator, jacobian, residuals, result.undetermined);
  result.coveredResiduals = evaluator.coveredResiduals();
  result.stdDev = standardDeviations(spec, problem, blocks, cost, result);
  result.renders = callback.renders() + (resumed ? resume->renders : 0);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() +
                   (resumed ? resume->seconds : 0.0);
  return result;
}

}  // namespace lpvlab
