#pragma once
// A fit's outputs, in its directory (each written to a temporary name and renamed):
//   fit.json     the specification, the fitted values with their standard deviations, the
//                undetermined parameters, the singular values of the scaled Jacobian, the
//                convergence log (one entry per iteration), the error of every view (fitted and
//                held out) before (initial values) and after (fitted values), renderings, time
//   fitted.toml  the fitted (determined) parameters as experiment keys: an experiment that
//                writes include = ["fitted.toml"] runs the fitted variant

#include <string>

#include <nlohmann/json.hpp>

#include "framework/fit/fit_problem.h"

namespace lpvlab {

// The fitted.toml text: a comment naming the fit, then one table per stage with the determined
// parameters (each with its standard deviation as a comment).
std::string fittedToml(const FitSpec& spec, const FitResult& result);

nlohmann::json fitJson(const FitSpec& spec, const FitResult& result, const nlohmann::json& before,
                       const nlohmann::json& after);

// Writes DIR/fit.json and DIR/fitted.toml.
void writeFitOutputs(const std::string& dir, const FitSpec& spec, const FitResult& result,
                     const nlohmann::json& before, const nlohmann::json& after);

}  // namespace lpvlab
