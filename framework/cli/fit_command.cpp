// `lpvlab fit FILE`: fits the strategy constants named by FILE's [fit] table to the path-traced
// references of its views (docs/fitting.md), printing a line per iteration, and writes
// DIR/fit.json, DIR/fitted.toml and DIR/fit.md (framework/fit/fit_output.h). Its progress goes to
// DIR/fit.progress.json after every iteration, so an interrupted fit run again resumes
// (framework/fit/fit_checkpoint.h).

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "framework/core/log.h"
#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/core/progress.h"
#include "framework/fit/fit_checkpoint.h"
#include "framework/fit/fit_output.h"
#include "framework/gl/context.h"
#include "framework/core/atomic_file.h"

namespace lpvlab::cli {

namespace {

std::string parameterLine(const FitSpec& spec, const std::vector<double>& x) {
  std::string out;
  char buffer[64];
  for (std::size_t j = 0; j < x.size(); ++j) {
    std::snprintf(buffer, sizeof buffer, "%.6g", x[j]);
    out += (j ? ", " : "") + spec.parameters[j].key + "=" + buffer;
  }
  return out;
}

void printErrors(const char* when, const nlohmann::json& errors) {
  for (const auto& view : errors) {
    const auto& m = view["metrics"];
    std::printf("  %-6s %-20s %-9s rmse %.5g  rel_mse %.5g  flip %.4f\n", when,
                view["view"].get<std::string>().c_str(), view["held_out"].get<bool>() ? "held-out" : "fitted",
                m["rmse"].get<double>(), m["rel_mse"].get<double>(), m["flip"].get<double>());
  }
}

// A finished fit in `dir` (its outputs, and no progress: that is removed last) is not replaced
// unless --force, which removes its outputs first; an interrupted one resumes.
void refuseAFinishedFit(const std::string& dir, const std::string& progressPath, const Options& options) {
  const std::filesystem::path finished = std::filesystem::path(dir) / "fit.json";
  if (!std::filesystem::exists(finished) || std::filesystem::exists(progressPath)) return;
  if (!options.force)
    throw Error((options.out.empty() ? "fit directory " : "--out ") + dir +
                ": holds a finished fit (fit.json); --force replaces it (removing its outputs "
                "first), or choose another directory");
  for (const char* name : {"fit.json", "fitted.toml", "fit.md"})
    std::filesystem::remove(std::filesystem::path(dir) / name);
}

// The progress of an interrupted fit of this spec (`key`), from its last accepted step, said
// where it resumes; none for a new fit (another fit's progress is named and started over).
std::optional<FitProgress> resumedProgress(const std::string& progressPath, const std::string& key) {
  bool otherFit = false;
  std::optional<FitProgress> resume = readFitProgress(progressPath, key, &otherFit);
  if (resume && !resume->log.empty()) {
    const int stopped = resume->log.back().iteration;
    resume = resumePoint(*resume);  // after the last accepted step (fit_problem.h)
    log::info("fit: resuming after iteration " + std::to_string(resume->log.back().iteration) +
              (resume->log.back().iteration < stopped
                   ? " (the last accepted step; the rejected ones after it are done again)"
                   : "") +
              " from " + progressPath + " (delete it to start over)");
  } else if (otherFit) {
    log::info("fit: " + progressPath + " is another fit's progress (the file or its overrides "
              "changed): starting over");
  }
  return resume;
}

// The fitted values with their uncertainties, and the errors before and after.
void printResult(const FitSpec& spec, const FitResult& result, const nlohmann::json& before,
                 const nlohmann::json& after) {
  std::printf("%s after %zu iterations, %d renderings, %s: %s\n",
              result.converged ? "converged" : "NOT converged", result.log.empty() ? 0 : result.log.size() - 1,
              result.renders, ProgressBar::formatSeconds(result.seconds).c_str(), result.termination.c_str());
  for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
    if (result.undetermined[j])
      std::printf("  %-36s undetermined by the images (not fitted; initial %.6g)\n",
                  spec.parameters[j].key.c_str(), spec.parameters[j].initial);
    else
      std::printf("  %-36s %.6g +- %.2g (sandwich %.2g)  (initial %.6g)%s\n", spec.parameters[j].key.c_str(),
                  result.values[j], result.stdDev[j], result.sandwichStdDev[j], spec.parameters[j].initial,
                  result.atBound[j] ? "  at a bound: the uncertainty assumes it inactive" : "");
  }
  printErrors("before", before);
  printErrors("after", after);
}

}  // namespace

int fitCommand(const Options& options) {
  const FitSpec spec = readFitSpec(options.experiment, options.overrides);
  const std::string dir = options.out.empty()
                              ? "runs/" + std::filesystem::path(options.experiment).stem().string() + "-fit"
                              : options.out;
  requireOutputDirectory(dir, options.out.empty() ? "fit directory" : "--out");
  // Read before any rendering, so a damaged progress file stops the fit at once.
  const std::string progressPath = (std::filesystem::path(dir) / "fit.progress.json").string();
  refuseAFinishedFit(dir, progressPath, options);
  const std::string key = fitKey(spec);
  const std::optional<FitProgress> resume = resumedProgress(progressPath, key);
  std::filesystem::create_directories(dir);
  FitProgress progress = resume.value_or(FitProgress{});
  const int resumedIterations = resume ? resume->log.back().iteration : 0;

  const toml::node* backendNode = spec.base.at_path("gl.backend").node();
  const std::string backend = backendNode && backendNode->is_string() ? backendNode->as_string()->get() : "auto";
  std::unique_ptr<GlContext> context;
  try {
    context = GlContext::create(backend);
  } catch (const Error& error) {
    // "auto" on a machine where no GL context can be made: without GL (gl.backend = "none"),
    // where every stage of the fit's frames can run on the CPU (else its views are refused,
    // naming what needs GL).
    if (backend != "auto") throw;
    log::info("no GL context could be made (" + std::string(error.what()) +
              "): every stage runs on the CPU (gl.backend = \"none\")");
    context = GlContext::create("none");
  }
  log::info("fit " + spec.file + ": " + std::to_string(spec.parameters.size()) + " parameters, " +
            std::to_string(spec.views.size()) + " views fitted, " + std::to_string(spec.heldOut.size()) +
            " held out, on " + context->renderer());
  SceneCache scenes;
  std::vector<FitView> views = makeFitViews(spec, scenes);
  FitEvaluator evaluator(spec, std::move(views), std::move(scenes));
  std::vector<double> initial;
  for (const FitParameter& p : spec.parameters) initial.push_back(p.initial);
  const nlohmann::json before = evaluator.errors(initial);

  const auto start = std::chrono::steady_clock::now();
  const FitResult result = runFit(evaluator, [&](const FitIteration& it) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.log.push_back(it);
    progress.renders = it.renders;
    progress.seconds = it.seconds;
    writeFitProgress(progressPath, key, progress);
    const int doneHere = it.iteration - resumedIterations;
    const double perIteration = doneHere > 0 ? elapsed / doneHere : -1.0;  // "?" first
    std::fprintf(stderr, "fit: iteration %d/%d  cost %.6e  |gradient| %.3e  %s  %s  (%zu renderings, elapsed %s, at most %s more)\n",
                 it.iteration, spec.maxIterations, it.cost, it.gradientMaxNorm,
                 it.iteration == 0 ? "initial" : it.successful ? "step taken" : "step rejected",
                 parameterLine(spec, it.x).c_str(), std::size_t(progress.renders),
                 ProgressBar::formatSeconds(progress.seconds).c_str(),
                 ProgressBar::formatSeconds(perIteration * (spec.maxIterations - it.iteration)).c_str());
  }, resume ? &*resume : nullptr);
  const nlohmann::json after = evaluator.errors(result.values);
  writeFitOutputs(dir, spec, result, before, after);
  std::filesystem::remove(progressPath);  // the outputs record the finished fit

  printResult(spec, result, before, after);
  std::printf("wrote %s/{fit.json, fitted.toml, fit.md}\n", dir.c_str());
  return 0;
}

}  // namespace lpvlab::cli
