#include "framework/fit/fit_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "framework/core/error.h"
#include "framework/core/atomic_file.h"
#include "framework/io/provenance.h"

namespace lpvlab {

namespace {

// Enough digits to read the double back exactly, and always a TOML float ("1.0", not "1").
std::string realText(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  std::string s = buffer;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string shortText(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

nlohmann::json finiteOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

std::string fittedToml(const FitSpec& spec, const FitResult& result) {
  std::map<std::string, std::string> stages;  // stage -> its lines
  std::string undetermined;
  for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
    const std::string& key = spec.parameters[j].key;
    const auto dot = key.find('.');
    if (result.undetermined[j]) {
      undetermined += (undetermined.empty() ? "" : ", ") + key;
      continue;
    }
    stages[key.substr(0, dot)] += key.substr(dot + 1) + " = " + realText(result.values[j]) +
                                  "   # +- " + shortText(result.stdDev[j]) + " (1 sigma; tiled sandwich +- " +
                                  shortText(result.sandwichStdDev[j]) + ")" +
                                  (result.atBound[j] ? ", at a bound of the fit" : "") + "\n";
  }
  std::ostringstream s;
  s << "# Fitted by lpvlab fit " << std::filesystem::absolute(spec.file).lexically_normal().string()
    << " (" << utcTimestamp() << "): " << (result.converged ? "converged" : "NOT converged") << ", "
    << result.termination << "\n"
    << "# Use it in an experiment: include = [\"fitted.toml\"] (a path relative to that file).\n";
  if (!undetermined.empty())
    s << "# Undetermined by the images, hence left out: " << undetermined << "\n";
  for (const auto& [stage, lines] : stages) s << "\n[" << stage << "]\n" << lines;
  return s.str();
}

namespace {

// How parameter j's Jacobian column was found, for people and fit.json.
std::string derivativeMethod(const FitResult& result, std::size_t j) {
  if (j < result.derivatives.size() && result.derivatives[j].empty())
    return "automatic (dual numbers through the frames)";
  return "central differences" +
         (j < result.derivatives.size() ? " (" + result.derivatives[j] + ")" : std::string());
}

}  // namespace

nlohmann::json iterationJson(const FitIteration& it) {
  return {{"iteration", it.iteration},
          {"cost", it.cost},
          {"gradient_max_norm", it.gradientMaxNorm},
          {"step_norm", it.stepNorm},
          {"step_successful", it.successful},
          {"seconds", it.seconds},
          {"x", it.x}};
}

nlohmann::json fitJson(const FitSpec& spec, const FitResult& result, const nlohmann::json& before,
                       const nlohmann::json& after) {
  nlohmann::json parameters = nlohmann::json::array();
  for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
    const FitParameter& p = spec.parameters[j];
    parameters.push_back({{"key", p.key},
                          {"initial", p.initial},
                          {"lower", finiteOrNull(p.lower > -1e300 ? p.lower : NAN)},
                          {"upper", finiteOrNull(p.upper < 1e300 ? p.upper : NAN)},
                          {"value", result.values[j]},
                          {"std_dev", finiteOrNull(result.stdDev[j])},
                          {"std_dev_sandwich", finiteOrNull(result.sandwichStdDev[j])},
                          {"undetermined", bool(result.undetermined[j])},
                          {"at_bound", bool(result.atBound[j])},
                          {"derivatives", derivativeMethod(result, j)}});
  }
  nlohmann::json log = nlohmann::json::array();
  for (const FitIteration& it : result.log) log.push_back(iterationJson(it));
  nlohmann::json views = nlohmann::json::array(), heldOut = nlohmann::json::array();
  for (const FitViewSpec& v : spec.views) views.push_back(v.name);
  for (const FitViewSpec& v : spec.heldOut) heldOut.push_back(v.name);
  return {{"lpvlab_version", LPVLAB_VERSION},
          {"experiment_file", std::filesystem::absolute(spec.file).lexically_normal().string()},
          {"created_utc", utcTimestamp()},
          {"git_revision", lpvlabRevision()},
          {"settings", {{"residual", residualName(spec.residual)}, {"epsilon", spec.epsilon},
                        {"loss", lossName(spec.loss)}, {"loss_scale", spec.lossScale},
                        {"step", spec.relativeStep}, {"max_iterations", spec.maxIterations},
                        {"rank_tolerance", spec.rankTolerance},
                        {"derivatives", derivativeName(spec.derivatives)},
                        {"covariance", "Ceres DENSE_SVD, scaled by 2 cost / (n - p)"},
                        {"sandwich_tile", spec.tile}}},
          {"views", views},
          {"held_out", heldOut},
          {"parameters", parameters},
          {"undetermined", [&] {
             nlohmann::json u = nlohmann::json::array();
             for (std::size_t j = 0; j < spec.parameters.size(); ++j)
               if (result.undetermined[j]) u.push_back(spec.parameters[j].key);
             return u;
           }()},
          {"singular_values", result.singularValues},
          {"initial_cost", result.initialCost},
          {"final_cost", result.finalCost},
          {"covered_residuals", result.coveredResiduals},
          {"converged", result.converged},
          {"termination", result.termination},
          {"renders", result.renders},
          {"seconds", result.seconds},
          {"convergence", log},
          {"error_before", before},
          {"error_after", after}};
}

double significanceSigma(const FitResult& result, std::size_t j) {
  return std::max(result.stdDev[j], result.sandwichStdDev[j]);
}

namespace {

std::string format(const char* pattern, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, v);
  return buffer;
}

// The relative drop from `before` to `after`: positive when the fit helped.
std::string gain(double before, double after) {
  return before > 0.0 ? format("%+.1f%%", 100.0 * (before - after) / before) : "-";
}

const nlohmann::json& metricsOf(const nlohmann::json& errors, const std::string& view) {
  for (const auto& e : errors)
    if (e["view"] == view) return e["metrics"];
  throw Error("fit report: no error figures for view '" + view + "'");
}

}  // namespace

std::string fitReport(const FitSpec& spec, const FitResult& result, const nlohmann::json& before,
                      const nlohmann::json& after) {
  std::ostringstream s;
  s << "# Fit report: " << std::filesystem::path(spec.file).filename().string() << "\n\n"
    << "File " << std::filesystem::absolute(spec.file).lexically_normal().string() << ", "
    << utcTimestamp() << ", revision " << lpvlabRevision() << ".\n"
    << (result.converged ? "Converged" : "**Not converged**") << " after "
    << (result.log.empty() ? 0 : result.log.size() - 1) << " iterations (" << result.termination
    << "); " << result.renders << " renderings in " << format("%.0f", result.seconds)
    << " s. Cost " << format("%.6g", result.initialCost) << " -> " << format("%.6g", result.finalCost)
    << ".\n\n## Parameters\n\n"
    << "sigma: Ceres's DENSE_SVD covariance scaled by the residual variance, which assumes independent "
       "pixel errors: a lower bound, since neighbouring pixels share the LPV's errors. "
       "sandwich: (J^T J)^-1 (sum over " << spec.tile << "x" << spec.tile << "-pixel tiles of "
       "J_t^T r_t r_t^T J_t) (J^T J)^-1, which allows for errors correlated within a tile (not "
       "across tiles). z = (fitted - published) / the larger of the two; |z| > 3: the fitted value "
       "differs significantly from the published (= initial) one.\n\n"
    << "| parameter | published | fitted | sigma | sandwich | z | verdict |\n"
    << "|---|---|---|---|---|---|---|\n";
  for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
    const FitParameter& p = spec.parameters[j];
    s << "| `" << p.key << "` | " << format("%.6g", p.initial) << " | ";
    if (result.undetermined[j]) {
      s << "- | - | - | - | undetermined by the images (not fitted) |\n";
      continue;
    }
    const double sigma = significanceSigma(result, j);
    const double z = (result.values[j] - p.initial) / sigma;
    s << format("%.6g", result.values[j]) << " | " << format("%.3g", result.stdDev[j]) << " | "
      << format("%.3g", result.sandwichStdDev[j]) << " | " << format("%.2f", z) << " | "
      << (std::abs(z) > 3.0 ? "differs significantly" : "not significantly different")
      << (result.atBound[j] ? " (at a bound of the fit: sigma assumes it inactive)" : "") << " |\n";
  }
  s << "\n## Derivatives\n\n";
  for (std::size_t j = 0; j < spec.parameters.size(); ++j)
    s << "- `" << spec.parameters[j].key << "`: " << derivativeMethod(result, j) << "\n";
  s << "\n## Error of `indirect` against the reference's `indirect1`\n\n"
       "Before: the published values; after: the fitted ones. Gain: the relative drop of the "
       "error (positive: the fit helped).\n";
  for (const bool heldOut : {false, true}) {
    const std::vector<FitViewSpec>& views = heldOut ? spec.heldOut : spec.views;
    if (views.empty()) continue;
    s << "\n### " << (heldOut ? "Held-out views" : "Fitted views") << "\n\n"
      << "| view | RMSE before | after | gain | rel_mse before | after | gain | FLIP before | after | gain |\n"
      << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const FitViewSpec& v : views) {
      const nlohmann::json &b = metricsOf(before, v.name), &a = metricsOf(after, v.name);
      s << "| " << v.name;
      for (const char* metric : {"rmse", "rel_mse", "flip"}) {
        const double x = b[metric].get<double>(), y = a[metric].get<double>();
        s << " | " << format("%.4g", x) << " | " << format("%.4g", y) << " | " << gain(x, y);
      }
      s << " |\n";
    }
  }
  return s.str();
}

void writeFitOutputs(const std::string& dir, const FitSpec& spec, const FitResult& result,
                     const nlohmann::json& before, const nlohmann::json& after) {
  const std::filesystem::path d(dir);
  std::filesystem::create_directories(d);
  writeTextAtomically((d / "fitted.toml").string(), fittedToml(spec, result));
  writeTextAtomically((d / "fit.json").string(), fitJson(spec, result, before, after).dump(2) + "\n");
  writeTextAtomically((d / "fit.md").string(), fitReport(spec, result, before, after));
}

}  // namespace lpvlab
