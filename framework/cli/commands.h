#pragma once
// The subcommands behind lpvlab's CLI; each returns the process exit code.

#include <map>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/cli/slurm_script.h"

namespace lpvlab::cli {

struct Options {
  std::string experiment;                 // "" = the built-in default
  std::string out;
  std::vector<std::string> overrides;     // "key.path=value"
  bool dumpGrid = false;                  // run: -s output.dump_grid=true
  std::vector<int> gridSizes{16, 32, 64};
  std::vector<int> iterationCounts{1, 4, 16, 64};
  std::string csv;
  std::string cacheDir;                   // "" = the default reference cache
  bool tracer = false;                    // bench the path tracer instead of the LPV pipeline
  int tracerSamples = 4;                  // samples per pixel per timed pass
  std::vector<std::string> tracerIsas;    // bench --tracer: instruction sets ("all": every one the CPU has)
  std::vector<int> tracerWidths;          // bench --tracer: query widths (0: native)
  int jobs = 1;                           // sweep: configurations run in parallel
  std::string emit;                       // sweep: "slurm" = write a job-array script, run nothing
  SlurmOptions slurm;                     // sweep --emit slurm: what each job asks for
  std::optional<int> refCpus;             // sweep --emit slurm: the references' (default: the
  std::optional<std::string> refMem;      //   tasks' --cpus-per-task, --mem, --time)
  std::optional<std::string> refTime;
  std::string metric;                     // report: the error metric of the speed/accuracy plot
  std::string reportTime;                 // report: the speed axis, "method", "total" or "gpu-estimate" ("": method)
  std::string reportGpu;                  // report: the GPU of "gpu-estimate" ("": the report's default)
  std::vector<std::string> moreSweeps;    // report: further sweep directories in the same report
  std::string reportOut;                  // report: where it goes ("": DIR/report)
  std::vector<std::string> images;        // compare: TEST and REFERENCE (run directories or EXRs)
  std::vector<std::string> aovs;          // compare: the AOVs (default direct, indirect)
  std::vector<std::string> thresholds;    // compare: NAME=VALUE bounds; exit 3 beyond one
  bool json = false;                      // compare, list: JSON instead of the text
  bool force = false;                     // run, fit, sweep: replace a finished run, fit or other sweep in --out
  std::optional<double> tuneBudgetMs;     // tune: --budget-ms (replaces the file's goal)
  std::optional<double> tuneError;        // tune: --error
  int explainVpls = 2048;                 // explain: VPLs per draw (rsm_vpl_subset.h)
  std::string shell;                      // completion: the shell whose script to print
};

// "compute: BACKEND; on the CPU: [direct, ]TABLES" from a Pipeline::computeReport().
std::string computeLine(const nlohmann::json& compute);
// How a stage's time was taken, for the console: "GL timer query" or "CPU wall clock" (a
// TimingReport's clock name; "mixed" for a total over both).
std::string clockLabel(const std::string& clock);
// "times: GL timer queries on RENDERER (stages); CPU wall clock on CPU (stages)" from a
// TimingReport's clock map (total left out).
std::string clocksLine(const std::map<std::string, std::string>& clock, const std::string& renderer,
                       const std::string& cpu);

int runCommand(const Options& options);
int benchCommand(const Options& options);
int referenceCommand(const Options& options);
int benchTracerCommand(const Options& options);
int sweepCommand(const Options& options);    // options.out: the sweep directory
int summaryCommand(const Options& options);  // options.out: the sweep directory
int reportCommand(const Options& options);
int compareCommand(const Options& options);   // options.out: the sweep directory
int fitCommand(const Options& options);
int explainCommand(const Options& options);
int tuneCommand(const Options& options);  // options.out: the tune's directory  // options.out: the explanation's directory      // options.out: the fit's directory
int listCommand(bool json);  // json: `lpvlab list --json`
int infoCommand(const Options& options);  // options.experiment holds the scene

}  // namespace lpvlab::cli
