#pragma once
// The [tune] table of an experiment file: what `lpvlab tune` searches, on which views, for which
// goal (docs/tuning.md). The rest of the file is the configuration the search starts from (the
// baseline, which every rung measures beside the candidates).
//
//   [tune]
//   metric = "indirect_vs_indirect1.block_nrmse"  # <pair>.<metric> of the runs' comparisons; lower is better
//   time = "method"             # the frame time bounded: method (its own stages) | total (the frame)
//                               # | gpu-estimate (the method's GL kernels estimated on `gpu`)
//   gpu = "h100_sxm"            # with time = "gpu-estimate": a key of analysis's gpus.toml
//   budget_ms = 40.0            # the least error within this median frame time ("baseline": the
//                               # baseline's own, measured at each rung beside the candidates), or ...
//   error = 0.5                 # ... the least time within this error (exactly one; --budget-ms, --error)
//   candidates = 27             # configurations drawn from the space
//   eta = 3                     # each rung keeps the best 1 / eta of them
//   rungs = [16, 64, 256]       # the reference's samples per pixel at each rung: cheap, noisy
//                               # comparisons first, the survivors against better references
//   seed = 1                    # of the draws
//   [tune.space]                # each key: a list of choices, or a range
//   "grid.resolution" = [16, 24, 32, 48]
//   "occlusion.type" = ["none", "geometry_volume"]
//   "injection.shift" = { min = 0.0, max = 2.0, step = 0.25 }   # step: values on its grid
//   "propagation.iterations" = { min = 4, max = 64, log = true }  # integers stay integers
//   [tune.fit]                  # optional: the chosen configuration's constants then fitted
//   parameters = [{ key = "propagation.far_face_solid_angle", lower = 0.0, upper = 2.1 }]
//                               # ... as a [fit] table (lpvlab fit), on the tuned views
//   [[tune.views]]              # tuned on, as [[fit.views]] (none: the file's own view)
//   [[tune.held_out]]           # measured for the chosen configuration and the baseline only
//
// Every bad input is an Error naming the file, the key and the problem.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "framework/experiment/named_views.h"

namespace lpvlab {

struct TuneDimension {
  std::string key;                  // "<table>.<name>" of the experiment
  std::vector<std::string> choices; // TOML value texts; empty for a range
  double min = 0.0, max = 0.0;      // a range
  double step = 0.0;                // > 0: values on min + k step
  bool log = false;                 // drawn uniformly in log(value)
  bool integer = false;             // min and max were integers: so are the values
};

struct TuneSpec {
  std::string file;
  toml::table base;                 // the file's table, extends and includes merged, no [tune]
  std::string pair = "indirect_vs_indirect1";
  std::string metric = "block_nrmse";
  std::string time = "method";     // "method", "total" or "gpu-estimate"
  std::string gpu = "h100_sxm";     // time = "gpu-estimate": the GPU, a key of gpus.toml
  std::optional<double> budgetMs;
  bool budgetIsBaseline = false;    // budget_ms = "baseline": budgetMs is set per rung from it
  std::optional<double> maxError;
  int candidates = 27;
  int eta = 3;
  std::vector<int> rungs{16, 64, 256};
  std::uint64_t seed = 1;
  std::vector<TuneDimension> space;
  std::vector<NamedView> views;     // the file's own view when none is given
  std::vector<NamedView> heldOut;
  // [tune.fit]: the [fit] table of `lpvlab fit` on the chosen configuration, with the tuned
  // views as its [[fit.views]] (their scene files absolute); none without it.
  std::optional<toml::table> fit;
};

// Reads `path` with the -s overrides applied; `budgetMs` / `maxError` (the command line's) replace
// the file's goal.
TuneSpec readTuneSpec(const std::string& path, const std::vector<std::string>& overrides,
                      std::optional<double> budgetMs, std::optional<double> maxError);

}  // namespace lpvlab
