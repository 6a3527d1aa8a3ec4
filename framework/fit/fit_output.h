#pragma once
// A fit's outputs, in its directory (each written to a temporary name and renamed):
//   fit.json     the specification, the fitted values with their standard deviations, the
//                undetermined parameters, the singular values of the scaled Jacobian, the
//                convergence log (one entry per iteration), the error of every view (fitted and
//                held out) before (initial values) and after (fitted values), renderings, time
//   fitted.toml  the fitted (determined) parameters as experiment keys: an experiment that
//                writes include = ["fitted.toml"] runs the fitted variant
//   fit.md       the report for people: per parameter the published (initial) and fitted value,
//                both deviations, z and whether it differs significantly; per view, fitted and
//                held out, the error before and after and the gain

#include <string>

#include <nlohmann/json.hpp>

#include "framework/fit/fit_problem.h"

namespace lpvlab {

// The fitted.toml text: a comment naming the fit, then one table per stage with the determined
// parameters (each with its standard deviation as a comment).
std::string fittedToml(const FitSpec& spec, const FitResult& result);

// One iteration of the convergence log as fit.json and fit.progress.json write it.
nlohmann::json iterationJson(const FitIteration& it);

nlohmann::json fitJson(const FitSpec& spec, const FitResult& result, const nlohmann::json& before,
                       const nlohmann::json& after);

// The deviation that decides significance: the larger of Ceres's (independent pixels) and the
// tiled sandwich (fit_covariance.h); neither sees correlation across tiles, so both are low.
double significanceSigma(const FitResult& result, std::size_t parameter);

// The fit.md text (Markdown). `before` and `after` are FitEvaluator::errors at the initial and
// the fitted values.
std::string fitReport(const FitSpec& spec, const FitResult& result, const nlohmann::json& before,
                      const nlohmann::json& after);

// Writes DIR/fit.json, DIR/fitted.toml and DIR/fit.md.
void writeFitOutputs(const std::string& dir, const FitSpec& spec, const FitResult& result,
                     const nlohmann::json& before, const nlohmann::json& after);

}  // namespace lpvlab
