// lpvlab's command line: `lpvlab run [FILE]`, `lpvlab bench [FILE]`, `lpvlab list`,
// `lpvlab info SCENE`, `lpvlab reference [FILE]`, `lpvlab sweep FILE`, `lpvlab summary DIR`,
// `lpvlab report DIR`, `lpvlab fit FILE`, `lpvlab explain FILE`, `lpvlab tune FILE`,
// `lpvlab compare TEST REFERENCE`,
// `lpvlab completion bash`.
// Every failure below this point is an lpvlab::Error (or a library exception); it is printed
// once, as "lpvlab: error: <where>: <what>", and the exit code is 1; a usage error (an unknown
// command or option, a missing argument) is one such line too, with exit code 2.

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/cli/completion.h"
#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/io/provenance.h"

namespace lpvlab {
namespace {

using cli::Options;

// A command: its CLI11 subcommand (options bound to an Options) and what runs when it is parsed.
struct Command {
  CLI::App* app;
  std::function<int()> action;
};

Command addRun(CLI::App& app, Options& o) {
  CLI::App* run = app.add_subcommand(
      "run", "Run one experiment (default: the built-in Cornell box) into its own directory");
  run->add_option("experiment", o.experiment, "Experiment file (TOML); omit for the default");
  run->add_option("-o,--out", o.out, "Output directory (default: runs/<name>-<UTC time>)");
  run->add_flag("--force", o.force,
                "Replace a finished run in the output directory (its files are removed first)");
  run->add_option("-s,--set", o.overrides,
                  "Override one parameter, e.g. -s propagation.iterations=16 (repeatable)");
  run->add_flag("--dump-grid", o.dumpGrid,
                "Also write the light grid after the last frame (grid.npy, grid.json: SH "
                "coefficients per cell and level); the same as -s output.dump_grid=true");
  return {run, [&o] { return cli::runCommand(o); }};
}

Command addBench(CLI::App& app, Options& o) {
  CLI::App* bench = app.add_subcommand(
      "bench", "Per-stage times and propagation throughput over grid sizes and iteration counts");
  bench->add_option("experiment", o.experiment, "Experiment file (default: the Cornell box)");
  bench->add_option("-s,--set", o.overrides, "Override one parameter (repeatable)");
  bench->add_option("--grids", o.gridSizes, "Grid resolutions to measure")->delimiter(',');
  bench->add_option("--iterations", o.iterationCounts, "Iteration counts")->delimiter(',');
  bench->add_option("--csv", o.csv, "Also write the table as CSV to this file");
  bench->add_flag("--tracer", o.tracer,
                  "Measure the reference path tracer instead: paths/s and rays/s");
  bench->add_option("--spp", o.tracerSamples, "With --tracer: samples per pixel per pass")
      ->check(CLI::Range(1, 1 << 20));
  bench
      ->add_option("--isa", o.tracerIsas,
                   "With --tracer: Embree instruction sets to measure (sse4.2, avx, avx2, avx512, "
                   "auto; all = every one this CPU has)")
      ->delimiter(',');
  bench
      ->add_option("--packet-width", o.tracerWidths,
                   "With --tracer: rays per Embree query to measure (0 = native, 1, 4, 8, 16)")
      ->delimiter(',');
  return {bench, [&o] { return o.tracer ? cli::benchTracerCommand(o) : cli::benchCommand(o); }};
}

Command addReference(CLI::App& app, Options& o) {
  CLI::App* reference = app.add_subcommand(
      "reference", "Render (or reuse from the cache) the path-traced reference of an experiment");
  reference->add_option("experiment", o.experiment, "Experiment file (default: the Cornell box)");
  reference->add_option("-s,--set", o.overrides, "Override one parameter (repeatable)");
  reference->add_option("--cache", o.cacheDir,
                        "Reference cache folder (default: $LPVLAB_CACHE_DIR or .cache/references)");
  return {reference, [&o] { return cli::referenceCommand(o); }};
}

Command addSweep(CLI::App& app, Options& o) {
  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "Run every configuration of an experiment's [sweep] table, each into DIR/<id>/ "
      "(resumable: complete configurations are skipped), then write DIR/summary.csv");
  sweep->add_option("experiment", o.experiment, "Experiment file (TOML) with a [sweep] table")
      ->required();
  sweep->add_option("-o,--out", o.out, "Sweep directory (default: runs/<file stem>-sweep)");
  sweep->add_option("-j,--jobs", o.jobs, "Configurations run in parallel (child processes)")
      ->check(CLI::Range(1, 1024));
  sweep->add_flag("--force", o.force,
                  "Replace another sweep in the sweep directory (its runs are removed first)");
  sweep->add_option("-s,--set", o.overrides,
                    "Override one parameter of every configuration (repeatable)");
  sweep
      ->add_option("--emit", o.emit,
                   "slurm: write DIR/sweep.slurm (a job array), DIR/submit.sh and the "
                   "configurations; run nothing")
      ->check(CLI::IsMember({"slurm"}));
  sweep->add_option("--cpus-per-task", o.slurm.tasks.cpusPerTask,
                    "With --emit slurm: CPUs of each job (default 2)");
  sweep->add_option("--mem", o.slurm.tasks.memory,
                    "With --emit slurm: memory of each job (default 4G)");
  sweep->add_option("--time", o.slurm.tasks.time,
                    "With --emit slurm: time limit of each job (default 01:00:00)");
  sweep->add_option("--ref-cpus-per-task", o.refCpus,
                    "With --emit slurm: CPUs of each reference's job (default: --cpus-per-task)");
  sweep->add_option("--ref-mem", o.refMem,
                    "With --emit slurm: memory of each reference's job (default: --mem)");
  sweep->add_option("--ref-time", o.refTime,
                    "With --emit slurm: time limit of each reference's job (default: --time)");
  sweep->add_flag("--exclusive", o.slurm.exclusive,
                  "With --emit slurm: each task on nodes of its own (for timing sweeps)");
  sweep->add_option("--gres", o.slurm.gres,
                    "With --emit slurm: generic resources of each task, e.g. gpu:1; the runs "
                    "then use GL through EGL (gl.backend = \"egl\")");
  sweep->add_option("--array-throttle", o.slurm.throttle,
                    "With --emit slurm: at most this many tasks at once (default 0: no cap)");
  return {sweep, [&o] { return cli::sweepCommand(o); }};
}

Command addSummary(CLI::App& app, Options& o) {
  CLI::App* summary = app.add_subcommand(
      "summary", "Rebuild DIR/summary.csv from the manifests of a sweep directory");
  summary->add_option("dir", o.out, "Sweep directory")->required();
  return {summary, [&o] { return cli::summaryCommand(o); }};
}

Command addReport(CLI::App& app, Options& o) {
  CLI::App* report = app.add_subcommand(
      "report",
      "Build DIR/report/index.html: speed/accuracy plots, ablation table, images "
      "(several sweep directories: one report of them all, written to --out)");
  report->add_option("dir", o.out, "Sweep directory (with summary.csv)")->required();
  report->add_option("more", o.moreSweeps,
                     "Further sweep directories in the same report (e.g. one per scene)");
  report->add_option("--out", o.reportOut,
                     "Report directory (default DIR/report; required with several sweeps)");
  report->add_option(
      "--metric", o.metric,
      "Error metric of the speed/accuracy plot (default: indirect_vs_indirect1 rmse)");
  report
      ->add_option("--time", o.reportTime,
                   "The speed axis: method = the indirect method's own stages (default: what differs "
                   "between configurations), total = the whole frame with the raster passes, "
                   "gpu-estimate = the method's GL kernels estimated on --gpu (labelled an estimate)")
      ->check(CLI::IsMember({"method", "total", "gpu-estimate"}));
  report->add_option("--gpu", o.reportGpu,
                     "With --time gpu-estimate: the GPU, a key of analysis/lpvlab_analysis/gpus.toml "
                     "(default h100_sxm)");
  return {report, [&o] { return cli::reportCommand(o); }};
}

Command addFit(CLI::App& app, Options& o) {
  CLI::App* fit = app.add_subcommand(
      "fit",
      "Fit the strategy constants named by an experiment's [fit] table to the path-traced "
      "references of its views; write DIR/fit.json, DIR/fitted.toml and the report DIR/fit.md "
      "(resumable: an interrupted fit run again goes on from DIR/fit.progress.json)");
  fit->add_option("experiment", o.experiment, "Experiment file (TOML) with a [fit] table")
      ->required();
  fit->add_option("-o,--out", o.out, "Fit directory (default: runs/<file stem>-fit)");
  fit->add_flag("--force", o.force,
                "Replace a finished fit in the fit directory (its outputs are removed first)");
  fit->add_option("-s,--set", o.overrides, "Override one parameter (repeatable)");
  return {fit, [&o] { return cli::fitCommand(o); }};
}

Command addExplain(CLI::App& app, Options& o) {
  CLI::App* explain = app.add_subcommand(
      "explain",
      "LPV's error against its reference split by stage (injection, occlusion, propagation, "
      "rendering): one frame rendered again with each stage replaced by an exact counterpart "
      "computed on the CPU; writes DIR/explain.json and DIR/explain.exr (docs/explain.md)");
  explain->add_option("experiment", o.experiment, "Experiment file (default: the Cornell box)");
  explain->add_option("-o,--out", o.out, "Output directory (default: runs/<name>-explain)");
  explain->add_flag("--force", o.force, "Replace a finished explanation in the output directory");
  explain->add_option("-s,--set", o.overrides, "Override one parameter (repeatable)");
  explain
      ->add_option("--vpls", o.explainVpls,
                   "At most this many of the RSM's VPLs per draw (two draws): where the RSM holds "
                   "more, one per block of texels, chosen by flux (default 2048)")
      ->check(CLI::Range(1, 1 << 24));
  return {explain, [&o] { return cli::explainCommand(o); }};
}

Command addTune(CLI::App& app, Options& o) {
  CLI::App* tune = app.add_subcommand(
      "tune",
      "Search an experiment's [tune.space] for the least error within a frame-time budget, or the "
      "least time within an error, by successive halving over ever better references; writes "
      "DIR/tune.json, DIR/pareto.csv and DIR/chosen.toml (resumable; docs/tuning.md)");
  tune->add_option("experiment", o.experiment, "Experiment file (TOML) with a [tune] table")->required();
  tune->add_option("-o,--out", o.out, "Tune directory (default: runs/<file stem>-tune)");
  tune->add_flag("--force", o.force, "Replace another or a finished tune in the directory");
  tune->add_option("-s,--set", o.overrides, "Override one parameter (repeatable)");
  tune->add_option("--budget-ms", o.tuneBudgetMs, "The goal: the least error within this median frame time (ms)")
      ->check(CLI::PositiveNumber);
  tune->add_option("--error", o.tuneError, "The goal: the least time within this error (the [tune] metric)")
      ->check(CLI::PositiveNumber);
  tune->add_option("-j,--jobs", o.jobs, "Runs at a time (default 1: timings are what a tune compares)")
      ->check(CLI::Range(1, 256));
  return {tune, [&o] {
            if (o.tuneBudgetMs && o.tuneError) throw Error("--budget-ms and --error: give one goal, not both");
            return cli::tuneCommand(o);
          }};
}

Command addCompare(CLI::App& app, Options& o) {
  CLI::App* compare = app.add_subcommand(
      "compare",
      "How far one run's images are from another's (or from a reference's): per AOV the "
      "relative difference (mean, 99th percentile, maximum), RMSE, relative MSE, FLIP, SSIM, "
      "block nRMSE and the ratio of the means over the covered pixels");
  compare->add_option("images", o.images, "TEST and REFERENCE: run directories or EXR files")
      ->required()
      ->expected(2);
  compare->add_option("--aov", o.aovs,
                      "An AOV to compare, or TEST_AOV=REFERENCE_AOV (e.g. indirect=indirect1 against "
                      "a reference); repeatable; default direct, indirect");
  compare->add_flag("--json", o.json, "Print JSON instead of the table");
  compare->add_option("--threshold", o.thresholds,
                      "NAME=VALUE: exit 3 when an AOV's figure exceeds VALUE (mean, p99, max, rmse, "
                      "rel_mse, flip, block_nrmse); repeatable");
  compare->add_option("--out", o.out,
                      "Also write DIR/difference.exr: per AOV the signed and the relative difference");
  return {compare, [&o] { return cli::compareCommand(o); }};
}

Command addList(CLI::App& app, Options& o) {
  CLI::App* list = app.add_subcommand(
      "list", "List the strategies of every stage and the indirect methods beside LPV");
  list->add_flag("--json", o.json,
                 "Print JSON (stages, strategies, methods, resources, parameters' defaults)");
  return {list, [&o] { return cli::listCommand(o.json); }};
}

Command addInfo(CLI::App& app, Options& o) {
  CLI::App* info =
      app.add_subcommand("info", "Load a scene and print its size, bounds, lights and cameras");
  info->add_option("scene", o.experiment, "A scene file, shared:<path> or builtin:cornell_box")
      ->required();
  return {info, [&o] { return cli::infoCommand(o); }};
}

// `lpvlab completion bash`: the completion script of the commands above (completion.h).
Command addCompletion(CLI::App& app, Options& o) {
  CLI::App* completion = app.add_subcommand(
      "completion", "Print a bash completion script of lpvlab's commands and options "
                    "(source <(lpvlab completion bash))");
  completion->add_option("shell", o.shell, "The shell (bash)")->required()->check(CLI::IsMember({"bash"}));
  return {completion, [&app] {
            std::cout << cli::bashCompletion(app);
            return 0;
          }};
}

// A usage error as one line with the prefix every error has: --help and --version (CLI11's exit
// code 0) print as CLI11 prints them; the exit code of the rest is 2 (CLI11's own are 105-115).
int usageError(CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
  if (e.get_exit_code() == 0) return app.exit(e);
  // A first word that is no command: name it (CLI11 says only that a command is required).
  std::string commands;
  bool known = false;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    commands += (commands.empty() ? "" : ", ") + sub->get_name();
    known = known || (argc > 1 && sub->get_name() == argv[1]);
  }
  if (argc > 1 && argv[1][0] != '-' && !known)
    log::error("unknown command '" + echoed(argv[1]) + "' (commands: " + commands + ")");
  else
    log::error(std::string(e.what()) + " (lpvlab --help lists the commands)");
  return 2;
}

// -q / -v (anywhere on the line: every command inherits them), else LPVLAB_LOG_LEVEL; the level
// is exported so that the processes a command starts (a sweep's runs) print as it does.
void addVerbosity(CLI::App& app, bool& quiet, bool& verbose) {
  CLI::Option* q = app.add_flag("-q,--quiet", quiet, "Print only warnings and errors on stderr (no notes or progress)");
  CLI::Option* v = app.add_flag("-v,--verbose", verbose, "Also print how a run is set up (paths, choices, cache decisions)");
  q->excludes(v);
  q->configurable(false);
  v->configurable(false);
}

void applyVerbosity(bool quiet, bool verbose) {
  log::Level level = log::Level::Info;
  if (quiet) level = log::Level::Warning;
  else if (verbose) level = log::Level::Debug;
  else if (const char* name = std::getenv("LPVLAB_LOG_LEVEL"); name && !log::levelFromName(name, level))
    throw Error(std::string("LPVLAB_LOG_LEVEL: '") + name + "' is not quiet, normal or verbose");
  log::setLevel(level);
  ::setenv("LPVLAB_LOG_LEVEL", log::levelName(level), 1);
}

}  // namespace
}  // namespace lpvlab

int main(int argc, char** argv) {
  CLI::App app{"lpvlab: a research framework for Light Propagation Volumes variants"};
  app.require_subcommand(1);
  // The version a run's manifest records, and the source's git revision.
  app.set_version_flag("--version", []() {
    return std::string("lpvlab ") + LPVLAB_VERSION + " (git " + lpvlab::lpvlabRevision() + ")";
  });
  lpvlab::cli::Options options;
  bool quiet = false, verbose = false;
  lpvlab::addVerbosity(app, quiet, verbose);
  app.fallthrough();  // -q and -v after the command's name too
  // In the order --help lists them.
  const std::vector<lpvlab::Command> commands = {
      lpvlab::addRun(app, options),       lpvlab::addBench(app, options),
      lpvlab::addReference(app, options), lpvlab::addSweep(app, options),
      lpvlab::addSummary(app, options),   lpvlab::addReport(app, options),
      lpvlab::addFit(app, options),       lpvlab::addExplain(app, options),
      lpvlab::addTune(app, options),
      lpvlab::addCompare(app, options),
      lpvlab::addList(app, options),      lpvlab::addInfo(app, options),
      lpvlab::addCompletion(app, options)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return lpvlab::usageError(app, e, argc, argv);
  }
  try {
    lpvlab::applyVerbosity(quiet, verbose);
    for (const lpvlab::Command& command : commands)
      if (command.app->parsed()) return command.action();
    return 2;  // unreachable: require_subcommand(1)
  } catch (const std::exception& e) {
    lpvlab::log::error(e.what());
    return 1;
  }
}
