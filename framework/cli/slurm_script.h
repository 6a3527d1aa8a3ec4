#pragma once
// `lpvlab sweep --emit slurm`: the batch scripts that run a sweep on a Slurm cluster.
//
//   DIR/sweep.slurm       a job array: task i runs configuration i unless it is complete
//   DIR/references.slurm  only when configurations compare with a reference: a job array, task j
//                         renders (or reuses, at once, when the cache has it) distinct reference
//                         j, before the sweep's array starts
//   DIR/submit.sh         submits both, the sweep's array depending on the references'; its
//                         arguments are sbatch options for both jobs (they override the
//                         #SBATCH lines)
// For timing and GPU studies: --exclusive gives each sweep task whole nodes (no other job's load
// in its timings); --gres asks each task for GPUs (and the runs use GL through EGL); an array
// throttle caps how many tasks run at once. The references have resources and limits of their
// own (a path tracer on the CPU wants more cores and time than a run).
//
// Each script states the resources a task asks for and the environment lpvlab reads
// (LPVLAB_SHARED_DIR, LPVLAB_CACHE_DIR), as resolved when the scripts were written, instead of
// relying on sbatch copying the submitting shell's environment.

#include <filesystem>
#include <string>
#include <vector>

#include "framework/experiment/sweep_expansion.h"

namespace lpvlab::cli {

struct SlurmResources {
  int cpusPerTask = 2;
  std::string memory = "4G";      // sbatch --mem: a number with an optional K, M, G or T suffix
  std::string time = "01:00:00";  // sbatch --time: [D-]HH:MM:SS, HH:MM:SS, MM:SS or minutes
};

struct SlurmOptions {
  SlurmResources tasks;       // each configuration's task (--cpus-per-task, --mem, --time)
  SlurmResources references;  // each reference's task (--ref-cpus-per-task, --ref-mem, --ref-time)
  bool exclusive = false;     // --exclusive: each sweep task on nodes of its own
  std::string gres;           // --gres, e.g. gpu:1 ("": none)
  int throttle = 0;           // --array-throttle: at most this many tasks at once (0: no cap)
};

// Throws an Error naming the option when a value is not one sbatch accepts; `prefix` is the
// options' prefix in messages ("--" or "--ref-").
void checkSlurmResources(const SlurmResources& resources, const std::string& prefix = "--");
void checkSlurmOptions(const SlurmOptions& options);

// referenceKeys: per configuration, the key of the reference it compares with ("" for none).
void writeSlurmScripts(const std::filesystem::path& dir, const std::string& lpvlab,
                       const std::string& stem,
                       const std::vector<SweepConfiguration>& configurations,
                       const std::vector<std::string>& referenceKeys,
                       const SlurmOptions& options);

}  // namespace lpvlab::cli
