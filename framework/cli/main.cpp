// lpvlab's command line: `lpvlab run [FILE]`, `lpvlab bench [FILE]`, `lpvlab list`,
// `lpvlab info SCENE`, `lpvlab reference [FILE]`, `lpvlab sweep FILE`, `lpvlab summary DIR`,
// `lpvlab report DIR`, `lpvlab fit FILE`, `lpvlab compare TEST REFERENCE`.
// Every failure below this point is an lpvlab::Error (or a library exception); it is printed
// once, as "lpvlab: error: <where>: <what>", and the exit code is 1; a usage error (an unknown
// command or option, a missing argument) is one such line too, with exit code 2.

#include <CLI/CLI.hpp>

#include <iostream>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/io/provenance.h"

int main(int argc, char** argv) {
  CLI::App app{"lpvlab: a research framework for Light Propagation Volumes variants"};
  app.require_subcommand(1);
  // The version a run's manifest records, and the source's git revision.
  app.set_version_flag("--version", []() {
    return std::string("lpvlab ") + LPVLAB_VERSION + " (git " + lpvlab::lpvlabRevision() + ")";
  });
  lpvlab::cli::Options options;

  CLI::App* run = app.add_subcommand(
      "run", "Run one experiment (default: the built-in Cornell box) into its own directory");
  run->add_option("experiment", options.experiment, "Experiment file (TOML); omit for the default");
  run->add_option("-o,--out", options.out, "Output directory (default: runs/<name>-<UTC time>)");
  run->add_flag("--force", options.force,
                "Replace a finished run in the output directory (its files are removed first)");
  run->add_option("-s,--set", options.overrides,
                  "Override one parameter, e.g. -s propagation.iterations=16 (repeatable)");

  CLI::App* bench = app.add_subcommand(
      "bench", "Per-stage times and propagation throughput over grid sizes and iteration counts");
  bench->add_option("experiment", options.experiment, "Experiment file (default: the Cornell box)");
  bench->add_option("-s,--set", options.overrides, "Override one parameter (repeatable)");
  bench->add_option("--grids", options.gridSizes, "Grid resolutions to measure")->delimiter(',');
  bench->add_option("--iterations", options.iterationCounts, "Iteration counts")->delimiter(',');
  bench->add_option("--csv", options.csv, "Also write the table as CSV to this file");
  bench->add_flag("--tracer", options.tracer,
                  "Measure the reference path tracer instead: paths/s and rays/s");
  bench->add_option("--spp", options.tracerSamples, "With --tracer: samples per pixel per pass")
      ->check(CLI::Range(1, 1 << 20));
  bench->add_option("--isa", options.tracerIsas,
                    "With --tracer: Embree instruction sets to measure (sse4.2, avx, avx2, avx512, "
                    "auto; all = every one this CPU has)")
      ->delimiter(',');
  bench->add_option("--packet-width", options.tracerWidths,
                    "With --tracer: rays per Embree query to measure (0 = native, 1, 4, 8, 16)")
      ->delimiter(',');

  CLI::App* reference = app.add_subcommand(
      "reference", "Render (or reuse from the cache) the path-traced reference of an experiment");
  reference->add_option("experiment", options.experiment, "Experiment file (default: the Cornell box)");
  reference->add_option("-s,--set", options.overrides, "Override one parameter (repeatable)");
  reference->add_option("--cache", options.cacheDir,
                        "Reference cache folder (default: $LPVLAB_CACHE_DIR or .cache/references)");

  CLI::App* sweep = app.add_subcommand(
      "sweep", "Run every configuration of an experiment's [sweep] table, each into DIR/<id>/ "
               "(resumable: complete configurations are skipped), then write DIR/summary.csv");
  sweep->add_option("experiment", options.experiment, "Experiment file (TOML) with a [sweep] table")
      ->required();
  sweep->add_option("-o,--out", options.out, "Sweep directory (default: runs/<file stem>-sweep)");
  sweep->add_option("-j,--jobs", options.jobs, "Configurations run in parallel (child processes)")
      ->check(CLI::Range(1, 1024));
  sweep->add_flag("--force", options.force,
                  "Replace another sweep in the sweep directory (its runs are removed first)");
  sweep->add_option("-s,--set", options.overrides,
                    "Override one parameter of every configuration (repeatable)");
  sweep
      ->add_option("--emit", options.emit,
                   "slurm: write DIR/sweep.slurm (a job array), DIR/submit.sh and the "
                   "configurations; run nothing")
      ->check(CLI::IsMember({"slurm"}));
  sweep->add_option("--cpus-per-task", options.slurm.cpusPerTask,
                    "With --emit slurm: CPUs of each job (default 2)");
  sweep->add_option("--mem", options.slurm.memory,
                    "With --emit slurm: memory of each job (default 4G)");
  sweep->add_option("--time", options.slurm.time,
                    "With --emit slurm: time limit of each job (default 01:00:00)");

  CLI::App* summary = app.add_subcommand(
      "summary", "Rebuild DIR/summary.csv from the manifests of a sweep directory");
  summary->add_option("dir", options.out, "Sweep directory")->required();

  CLI::App* report = app.add_subcommand(
      "report", "Build DIR/report/index.html: speed/accuracy plots, ablation table, images "
                "(several sweep directories: one report of them all, written to --out)");
  report->add_option("dir", options.out, "Sweep directory (with summary.csv)")->required();
  report->add_option("more", options.moreSweeps,
                     "Further sweep directories in the same report (e.g. one per scene)");
  report->add_option("--out", options.reportOut,
                     "Report directory (default DIR/report; required with several sweeps)");
  report->add_option("--metric", options.metric,
                     "Error metric of the speed/accuracy plot (default: indirect_vs_indirect1 rmse)");

  CLI::App* fit = app.add_subcommand(
      "fit", "Fit the strategy constants named by an experiment's [fit] table to the path-traced "
             "references of its views; write DIR/fit.json, DIR/fitted.toml and the report DIR/fit.md "
             "(resumable: an interrupted fit run again goes on from DIR/fit.progress.json)");
  fit->add_option("experiment", options.experiment, "Experiment file (TOML) with a [fit] table")
      ->required();
  fit->add_option("-o,--out", options.out, "Fit directory (default: runs/<file stem>-fit)");
  fit->add_flag("--force", options.force,
                "Replace a finished fit in the fit directory (its outputs are removed first)");
  fit->add_option("-s,--set", options.overrides, "Override one parameter (repeatable)");

  CLI::App* compare = app.add_subcommand(
      "compare", "How far one run's images are from another's: per AOV the mean, 99th percentile "
                 "and maximum relative difference over the covered pixels");
  compare->add_option("images", options.images, "TEST and REFERENCE: run directories or EXR files")
      ->required()
      ->expected(2);
  compare->add_option("--aov", options.aovs, "An AOV to compare (repeatable; default direct, indirect)");
  compare->add_flag("--json", options.json, "Print JSON instead of the table");

  CLI::App* list =
      app.add_subcommand("list", "List the strategies of every stage and the indirect methods beside LPV");
  list->add_flag("--json", options.json,
                 "Print JSON (stages, strategies, methods, resources, parameters' defaults)");
  CLI::App* info = app.add_subcommand("info", "Load a scene and print its size, bounds, lights and cameras");
  info->add_option("scene", options.experiment, "A scene file, shared:<path> or builtin:cornell_box")
      ->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version (CLI11's exit code 0) print as CLI11 prints them; a usage error is one
    // line with the one prefix every error has, and exit code 2 (CLI11's own are 105-115).
    if (e.get_exit_code() == 0) return app.exit(e);
    // A first word that is no command: name it (CLI11 says only that a command is required).
    std::string commands;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
      commands += (commands.empty() ? "" : ", ") + sub->get_name();
      known = known || (argc > 1 && sub->get_name() == argv[1]);
    }
    if (argc > 1 && argv[1][0] != '-' && !known)
      std::cerr << "lpvlab: error: unknown command '" << lpvlab::echoed(argv[1])
                << "' (commands: " << commands << ")\n";
    else
      std::cerr << "lpvlab: error: " << e.what() << " (lpvlab --help lists the commands)\n";
    return 2;
  }
  try {
    if (run->parsed()) return lpvlab::cli::runCommand(options);
    if (bench->parsed())
      return options.tracer ? lpvlab::cli::benchTracerCommand(options)
                            : lpvlab::cli::benchCommand(options);
    if (info->parsed()) return lpvlab::cli::infoCommand(options);
    if (reference->parsed()) return lpvlab::cli::referenceCommand(options);
    if (sweep->parsed()) return lpvlab::cli::sweepCommand(options);
    if (summary->parsed()) return lpvlab::cli::summaryCommand(options);
    if (report->parsed()) return lpvlab::cli::reportCommand(options);
    if (compare->parsed()) return lpvlab::cli::compareCommand(options);
    if (fit->parsed()) return lpvlab::cli::fitCommand(options);
    return lpvlab::cli::listCommand(options.json);
  } catch (const std::exception& e) {
    std::cerr << "lpvlab: error: " << e.what() << "\n";
    return 1;
  }
}
