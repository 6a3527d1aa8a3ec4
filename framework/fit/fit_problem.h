#pragma once
// The fit: bounded nonlinear least squares over the evaluator's residuals (Ceres Solver 2.1,
// Levenberg-Marquardt with dense QR), derivatives automatic or by central differences through the
// pipeline, then the parameters' uncertainty from Ceres's covariance (DENSE_SVD).
//
// Automatic derivatives (FitSpec::derivatives = automatic, the default): for each parameter whose
// derivatives every fitted view's composition carries (Pipeline::derivativeRefusal: the strategy
// lists it in differentiableParameters and every stage after it has a kernel on dual numbers),
// the Jacobian column is the chain rule of the residual (linear, relative, log, with the loss)
// times d indirect / d parameter from the frame run again on dual numbers
// (framework/pipeline/dual_frame.h): exact, no step to choose, one pass per view for up to four
// parameters, while the parameter is inside its bounds (at a bound, one-sided differences: see
// ImageCost::automatic). The others (the injection shift, which acts in steps and whose
// derivative is 0 almost everywhere; anything behind a stage without a dual kernel) take central
// differences:
// Central differences: the Jacobian column of parameter j is (r(x + h e_j) - r(x - h e_j)) / 2h
// with h = step * max(|x_j|, |initial_j|) (step * 1 when both are 0; `step` the parameter's own
// when it gives one, else the fit's); at a bound the difference
// is one-sided, so no rendering ever sees a value outside the bounds. Why step = 1e-3 by default:
// the images are float32, so a rendering carries rounding noise of about 1e-6 of its value, which
// a difference divides by h (1e-3 relative error of the derivative at h = 1e-3, 1e-1 at Ceres's
// default 1e-6), while the truncation error grows as h^2 (about (h k)^2 / 6 for a damping
// raised to the k-th power over k iterations: 2e-4 at k = 32). 1e-3 balances the two. A
// parameter that acts in steps (the injection shift moves each VPL into the cell it lands in,
// so small shifts change nothing) needs a step of its own wide enough to cross cells.
//
// Undetermined parameters: the Jacobian at the solution, each column scaled by its parameter's
// magnitude (max(|x_j|, |initial_j|), 1 when both are 0) so that the test does not depend on
// units, is decomposed (SVD); each singular value below rank_tolerance times the largest is a
// direction the images do not determine, and every parameter with a component above 0.1 along
// such a direction is reported undetermined (its value is not returned as fitted). The others'
// covariance is Ceres's (J^T J)^-1 (DENSE_SVD) with the undetermined ones held constant, scaled
// by the residual variance s^2 = 2 cost / (n - p) (n covered residuals, p determined parameters).
// That assumes independent pixel errors, so it is a lower bound; beside it the sandwich estimate
// clustered by image tiles of FitSpec::tile pixels (fit_covariance.h) allows for errors
// correlated within a tile.

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/fit/fit_evaluator.h"

namespace lpvlab {

struct FitIteration {
  int iteration = 0;
  double cost = 0.0;              // half the sum of squared residuals
  double gradientMaxNorm = 0.0;
  double stepNorm = 0.0;
  bool successful = false;        // the step was taken
  double seconds = 0.0;           // since the solve started
  std::vector<double> x;          // parameter values after the iteration
  int renders = 0;                // view renderings of the solve so far
  // The trust region's radius for the next step: a resumed solve starts with it, so that it takes
  // the steps the interrupted one would have taken (0: unknown, Ceres's initial radius).
  double trustRegionRadius = 0.0;
};

struct FitResult {
  std::vector<double> initial, values;
  std::vector<double> stdDev;     // NaN for undetermined parameters
  // The sandwich estimate over image tiles (fit_covariance.h), which allows for pixel errors
  // correlated within a tile; NaN for undetermined parameters.
  std::vector<double> sandwichStdDev;
  std::vector<bool> undetermined;
  // At a bound, where the standard deviation (which assumes the bound inactive) says little.
  std::vector<bool> atBound;
  std::vector<double> singularValues;  // of the scaled Jacobian, largest first
  // Per parameter how its Jacobian column was found: "" automatically (dual numbers through the
  // frames), else why not (central differences: FitEvaluator::automaticRefusals).
  std::vector<std::string> derivatives;
  double initialCost = 0.0, finalCost = 0.0;
  long long coveredResiduals = 0;
  std::string termination;        // Ceres's message
  bool converged = false;
  int renders = 0;                // view renderings done by the solve and the covariance
  double seconds = 0.0;
  std::vector<FitIteration> log;
};

// Where an interrupted fit left off (fit_checkpoint.h): its iterations so far (iteration 0 the
// start), and the renderings and seconds they took (the last iteration's).
struct FitProgress {
  std::vector<FitIteration> log;
  int renders = 0;
  double seconds = 0.0;
};

// Where a resumed solve restarts: `progress` cut after its last accepted iteration (its start if
// none was), with that iteration's renderings and seconds. Ceres's Levenberg-Marquardt state after
// an accepted step is x and the trust-region radius alone, which Solver::Options can set; after a
// rejected step it also holds the factor by which the next rejection shrinks the radius (doubled
// at each rejection), which it cannot. So the rejected iterations after the last accepted one are
// done again, and the resumed fit takes the very steps the uninterrupted one takes.
FitProgress resumePoint(const FitProgress& progress);

// Runs the fit; `onIteration` is called after each iteration (for progress lines and
// checkpoints). With `resume` the solve starts at resumePoint(*resume) with the iterations
// `max_iterations` leaves and that iteration's trust-region radius, and the log, numbering,
// renderings, time and initial cost continue it; Ceres's termination message counts the
// iterations of the whole fit.
FitResult runFit(FitEvaluator& evaluator,
                 const std::function<void(const FitIteration&)>& onIteration = {},
                 const FitProgress* resume = nullptr);

}  // namespace lpvlab
